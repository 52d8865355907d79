// Generates large NCT programs for the benchmarks: `gcx-bench-gen KIND LINES > file`.
//   lines   G1/G2 contour blocks (the CAM-output bulk the pipeline must stream)
//   holes   a G83 drilling cycle repeated at about LINES positions
//   macro   an NCT WHILE loop that emits LINES G1 blocks (the macro expansion pass)
//   oword   the same loop for LinuxCNC (o100 while ... o100 endwhile), for rs274
//   exprs   LINES blocks of assignments and bracketed expressions, none of them fit for the
//           fast path: the rate of the ANTLR grammar path (gcx check) and the macro pass
//   exprsngc the same blocks for LinuxCNC, whose assignments need the whole value in brackets
//   g83     LINES holes of one G83 peck cycle (Q5, E0.254 so the clearance equals LinuxCNC's
//           fixed 0.254 mm), starting above R (G98 to the initial level Z10)
//   g83ngc  the same holes for LinuxCNC: identical text without the E word, which rs274 rejects
//           (tests/differential/programs/42_cycle_g83_e shows the two move alike)
#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr,
                 "usage: gcx-bench-gen lines|holes|macro|oword|exprs|exprsngc|g83|g83ngc LINES\n");
    return 2;
  }
  const std::string kind = argv[1];
  const long n = std::atol(argv[2]);
  if (kind == "g83" || kind == "g83ngc") {
    // 5 pecks per hole (R2 to Z-20 by Q5), a 1000 x n/1000 grid of 0.5 mm pitch
    std::printf("(BENCHMARK %s %ld)\nG21 G90 G17 G94 G54\nG0 X0 Y0 Z10\nF200\n", kind.c_str(), n);
    std::printf("G98 G83 X0 Y0 Z-20 R2 Q5%s\n", kind == "g83" ? " E0.254" : "");
    for (long i = 1; i < n; ++i)
      std::printf("X%.1f Y%.1f\n", (i % 1000) * 0.5, (i / 1000) * 0.5);
    std::printf("G80\nM30\n");
    return 0;
  }
  std::printf("(BENCHMARK %s %ld)\nG21 G90 G17 G54 G0 X0 Y0 Z5\nG1 Z-1 F600\n", kind.c_str(), n);
  if (kind == "lines") {
    // a zig-zag of lines with a half circle every 4th block; stays within +-100 mm
    double x = 0, y = 0;
    for (long i = 3; i < n - 1; ++i) {
      if (i % 4 == 0) {
        std::printf("G2 X%.3f Y%.3f I0 J0.5 F800\n", x, y + 1.0);
        y += 1.0;
      } else {
        x = (i % 8 < 4) ? 100.0 - (i % 4) * 0.25 : -100.0 + (i % 4) * 0.25;
        std::printf("G1 X%.3f Y%.3f F1200\n", x, y);
      }
      if (y > 100) y = -100;
    }
  } else if (kind == "holes") {
    std::printf("G98 G83 X0 Y0 Z-20 R2 Q5 F200\n");
    for (long i = 4; i < n - 1; ++i)
      std::printf("X%.3f Y%.3f\n", (i % 1000) * 0.5, (i / 1000) * 0.5);
    std::printf("G80\n");
  } else if (kind == "exprs" || kind == "exprsngc") {
    // straight-line macro text: every block goes through the grammar (2+SIN: never a division
    // by zero)
    const bool ngc = kind == "exprsngc";
    for (long i = 3; i < n - 1; ++i) {
      if (i % 2 == 0)
        std::printf("#%ld=%s[#%ld+%ld.5]*2/[2+SIN[%ld]]%s\n", 100 + i % 50, ngc ? "[" : "",
                    100 + (i + 7) % 50, i % 97, i % 360, ngc ? "]" : "");
      else
        std::printf("G1 X[#%ld MOD 200] Y[[%ld MOD 200]-100] F1000\n", 100 + i % 50, i);
    }
  } else if (kind == "macro" || kind == "oword") {
    // LINES G1 blocks from one loop: a raster of 1 mm steps, X and Y in -100..99 mm
    const char* move = "G1 X[[#1MOD200]-100] Y[[FIX[#1/200]MOD200]-100] F1000";
    if (kind == "macro")
      std::printf("#1=0\nWHILE[#1LT%ld]DO1\n%s\n#1=#1+1\nEND1\n", n, move);
    else
      std::printf("#1=0\no100 while [#1 LT %ld]\n%s\n#1=[#1+1]\no100 endwhile\n", n, move);
  } else {
    std::fprintf(stderr, "unknown kind %s\n", kind.c_str());
    return 2;
  }
  std::printf("M30\n");
  return 0;
}
