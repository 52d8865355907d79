// The equivalence report as a person sees it: the page rendered by headless Chromium (Debian's
// `chromium`, installed by `make deps`), its screenshot decoded, and the colours of side A, side
// B and the divergence marker counted. Each count is checked against a page that lacks the
// thing counted, so a legend swatch alone cannot pass for a drawn path.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <png.h>

#include "report/equiv_html.h"
#include "report/equiv_page_samples.h"

namespace gcx::report {
namespace {

namespace fs = std::filesystem;

struct Rgb {
  int r, g, b;
};

Rgb parseColour(const char* hex) {
  const unsigned v = static_cast<unsigned>(std::stoul(std::string(hex + 1), nullptr, 16));
  return {static_cast<int>(v >> 16), static_cast<int>((v >> 8) & 0xff), static_cast<int>(v & 0xff)};
}

struct Screenshot {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  /// Pixels within `slack` of the colour in every channel.
  std::size_t count(const char* hex, int slack = 24) const {
    const Rgb c = parseColour(hex);
    std::size_t n = 0;
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3)
      n += std::abs(rgb[i] - c.r) <= slack && std::abs(rgb[i + 1] - c.g) <= slack &&
           std::abs(rgb[i + 2] - c.b) <= slack;
    return n;
  }
};

bool haveChromium() {
  return std::system("command -v chromium >/dev/null 2>&1") == 0;
}

// Writes the page, renders it at 1200 × 900 and decodes the PNG; fails the test on any error.
Screenshot render(const std::string& name, const EquivPage& page, const PathRecorder& a,
                  const PathRecorder& b) {
  const fs::path dir =
      fs::temp_directory_path() / fmt::format("gcx-report-{}-{}", name, ::getpid());
  fs::create_directories(dir);
  const fs::path html = dir / "report.html", png = dir / "shot.png";
  {
    std::ofstream out(html, std::ios::binary);
    writeEquivHtml(out, page, a, b);
  }
  const std::string cmd = fmt::format(
      "timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars "
      "--user-data-dir={} --screenshot={} --window-size=1200,900 file://{} >{} 2>&1",
      (dir / "profile").string(), png.string(), html.string(), (dir / "chromium.log").string());
  Screenshot shot;
  const int rc = std::system(cmd.c_str());
  EXPECT_EQ(rc, 0) << cmd;
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, png.c_str())) {
    ADD_FAILURE() << "no screenshot: " << png << ": " << img.message;
    return shot;
  }
  img.format = PNG_FORMAT_RGB;
  shot.rgb.resize(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, shot.rgb.data(), 0, nullptr))
    ADD_FAILURE() << "bad screenshot: " << img.message;
  shot.width = static_cast<int>(img.width);
  shot.height = static_cast<int>(img.height);
  if (!::testing::Test::HasFailure()) fs::remove_all(dir);
  return shot;
}

TEST(ReportRender, ChromiumDrawsBothPathsAndTheMarker) {
  if (!haveChromium())
    GTEST_SKIP() << "chromium is not installed (make deps installs it); the report's rendering "
                    "is not checked";
  PathRecorder a, b, none;
  test::recordSamplePaths(a, b);
  const Screenshot full = render("full", test::samplePage(), a, b);
  ASSERT_EQ(full.width, 1200);
  ASSERT_EQ(full.height, 900);

  EquivPage unmarked = test::samplePage();
  unmarked.divergence.reset();
  const Screenshot withoutB = render("without-b", unmarked, a, none);

  const std::size_t sideA = full.count(kSideAColour), sideB = full.count(kSideBColour),
                    marker = full.count(kMarkerColour);
  // A and B: a rectangle of about 330 mm drawn at several pixels per mm, minus the legend
  EXPECT_GT(sideA, 2000u);
  EXPECT_GT(sideB, 1000u);
  EXPECT_GT(marker, 300u);
  // without B's path only its legend swatch is left, without a divergence no marker at all
  EXPECT_LT(withoutB.count(kSideBColour), 200u);
  EXPECT_GT(withoutB.count(kSideAColour), 2000u);
  EXPECT_EQ(withoutB.count(kMarkerColour), 0u);
  std::cout << "pixels: A " << sideA << ", B " << sideB << ", marker " << marker
            << "; without B: B " << withoutB.count(kSideBColour) << "\n";
}

} // namespace
} // namespace gcx::report
