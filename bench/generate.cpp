// Generates large NCT programs for the benchmarks: `gcx-bench-gen KIND LINES > file`.
//   lines   G1/G2 contour blocks (the CAM-output bulk the pipeline must stream)
#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: gcx-bench-gen lines|holes LINES\n");
    return 2;
  }
  const std::string kind = argv[1];
  const long n = std::atol(argv[2]);
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
  } else {
    std::fprintf(stderr, "unknown kind %s\n", kind.c_str());
    return 2;
  }
  std::printf("M30\n");
  return 0;
}
