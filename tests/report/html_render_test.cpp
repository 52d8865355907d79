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
#include <sstream>

#include "report/equiv_html.h"
#include "report/equiv_page_samples.h"
#include "support/test_support.h"

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

// A fresh folder with the page written as report.html.
fs::path writePage(const std::string& name, const EquivPage& page, const PathRecorder& a,
                   const PathRecorder& b) {
  const fs::path dir =
      fs::temp_directory_path() / fmt::format("gcx-report-{}-{}", name, ::getpid());
  fs::create_directories(dir);
  std::ofstream out(dir / "report.html", std::ios::binary);
  writeEquivHtml(out, page, a, b);
  return dir;
}

// Runs headless Chromium on dir/report.html (plus `fragment`) at 1200 × 900 with `action`
// (--screenshot=..., --dump-dom); its standard output goes to dir/out.txt.
void chromium(const fs::path& dir, const std::string& action, const std::string& fragment = "") {
  const std::string cmd =
      fmt::format("timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars "
                  "--user-data-dir={} {} --window-size=1200,900 file://{}{} >{} 2>{}",
                  (dir / "profile").string(), action, (dir / "report.html").string(), fragment,
                  (dir / "out.txt").string(), (dir / "chromium.log").string());
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

// Renders the page and decodes the PNG; fails the test on any error.
Screenshot render(const std::string& name, const EquivPage& page, const PathRecorder& a,
                  const PathRecorder& b) {
  const fs::path dir = writePage(name, page, a, b), png = dir / "shot.png";
  chromium(dir, "--screenshot=" + png.string());
  Screenshot shot;
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

std::vector<double> numbers(const std::string& text) {
  std::vector<double> out;
  std::istringstream in(text);
  for (double v; in >> v;)
    out.push_back(v);
  return out;
}

std::string attribute(const std::string& dom, const std::string& element, const std::string& name) {
  const auto at = dom.find(element);
  if (at == std::string::npos) return {};
  const auto v = dom.find(name + "=\"", at) + name.size() + 2;
  return dom.substr(v, dom.find('"', v) - v);
}

TEST(ReportRender, OpeningAtDivergenceZoomsTheScriptThere) {
  if (!haveChromium()) GTEST_SKIP() << "chromium is not installed (make deps installs it)";
  PathRecorder a, b;
  test::recordSamplePaths(a, b);
  const fs::path dir = writePage("zoom", test::samplePage(), a, b);
  const std::string page = gcx::test::readFile(dir / "report.html");
  const auto home = numbers(attribute(page, "<svg id=\"plot\"", "viewBox"));
  ASSERT_EQ(home.size(), 4u);
  chromium(dir, "--dump-dom", "#at-divergence");
  const std::string dom = gcx::test::readFile(dir / "out.txt");
  // a twentieth of the whole drawing, centred on the marker at (100, −60)
  const auto zoomed = numbers(attribute(dom, "<svg id=\"plot\"", "viewBox"));
  ASSERT_EQ(zoomed.size(), 4u) << dom.substr(0, 2000);
  EXPECT_NEAR(zoomed[2], home[2] / 20, 1e-6);
  EXPECT_NEAR(zoomed[3], home[3] / 20, 1e-6);
  EXPECT_NEAR(zoomed[0] + zoomed[2] / 2, 100, 1e-6);
  EXPECT_NEAR(zoomed[1] + zoomed[3] / 2, -60, 1e-6);
  // the marker rescaled to its size on screen: about 20 times smaller in drawing units
  auto scale = [](const std::string& html) {
    const std::string t = attribute(html, "<g id=\"divergence\"", "transform");
    const auto at = t.find("scale(");
    return at == std::string::npos ? 0.0 : std::stod(t.substr(at + 6));
  };
  const double before = scale(page), after = scale(dom);
  ASSERT_GT(after, 0) << dom.substr(0, 2000);
  EXPECT_GT(before / after, 10) << before << " " << after;
  if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}

} // namespace
} // namespace gcx::report
