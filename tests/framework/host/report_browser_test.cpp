// The report of the example study (examples/studies/resolution_sweep.json) as a reader gets it:
// its HTML, then, when Chromium is installed (or named by VOROSEAL_CHROMIUM), the page loaded
// in headless Chromium at 1,400 px: no script errors, every picture loaded, the key columns
// within the window, the charts there; and a screenshot (kept at VOROSEAL_REPORT_SHOT if set).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "tests/framework/host/svg_check.h"

namespace voroseal {
namespace {

namespace fs = std::filesystem;
using test::count_of;

// The window of the bar in issue 25.
constexpr int kWindowWidth = 1400, kWindowHeight = 900;

struct Result {
  int exit_code = -1;
  std::string out;
};

Result shell(const std::string& command) {
  Result result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string source_dir() {
  const char* dir = std::getenv("VOROSEAL_SOURCE_DIR");
  return dir ? dir : ".";
}

// The Chromium to use: VOROSEAL_CHROMIUM, else the Debian package's; "" when there is none.
std::string chromium() {
  if (const char* named = std::getenv("VOROSEAL_CHROMIUM"))
    return ::access(named, X_OK) == 0 ? named : "";
  for (const char* path : {"/usr/bin/chromium", "/usr/bin/chromium-browser"})
    if (::access(path, X_OK) == 0) return path;
  return "";
}

// Runs the example study once for every test of the suite.
class ReportBrowser : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(fs::temp_directory_path() /
                        ("voroseal_report_browser_" + std::to_string(::getpid())));
    fs::remove_all(*dir_);
    fs::create_directories(*dir_);
    const std::string study = source_dir() + "/examples/studies/resolution_sweep.json";
    run_ = new Result(shell("'" VOROSEAL_EXECUTABLE "' --quiet --threads 2 run '" + study +
                            "' -o '" + (*dir_ / "study").string() + "' 2>&1"));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
    delete run_;
  }
  static fs::path report() { return *dir_ / "study" / "report.html"; }
  static fs::path* dir_;
  static Result* run_;
};
fs::path* ReportBrowser::dir_ = nullptr;
Result* ReportBrowser::run_ = nullptr;

TEST_F(ReportBrowser, TheExampleReportHasKeyColumnsChartsAndTetViews) {
  ASSERT_EQ(run_->exit_code, 0) << run_->out;
  const std::string html = read_text(report());
  EXPECT_EQ(test::markup_problem(html), "");
  const size_t key = html.find("<table class=\"key\">");
  const size_t all = html.find("<details class=\"all\">");
  ASSERT_NE(key, std::string::npos);
  ASSERT_NE(all, std::string::npos);
  const std::string key_table = html.substr(key, html.find("</table>", key) - key);
  for (const char* heading :
       {"model", "edge-length", "status", "regions kept", "triangles", "tets", "mean Q",
        "% tri. &lt; 30&deg;", "Hausdorff %", "min dihedral &deg;", "time s"})
    EXPECT_NE(key_table.find(">" + std::string(heading) + "</th>"), std::string::npos) << heading;
  EXPECT_EQ(count_of(key_table, "<tr class=\"ok\">"), 6u);
  EXPECT_EQ(key_table.find("thinnest_wedge"), std::string::npos) << "behind the toggle";
  EXPECT_NE(html.find("thinnest_wedge_deg", all), std::string::npos);
  // Five charts across runs, three histograms per run; a cut picture per run, on disk.
  EXPECT_EQ(count_of(html, "class=\"chart\""), 5u);
  EXPECT_EQ(count_of(html, "class=\"histogram\""), 6u * 3);
  const std::vector<std::string> images = test::attribute_values(html, "img", "src");
  EXPECT_EQ(images.size(), 12u);
  size_t cuts = 0;
  for (const std::string& src : images) {
    EXPECT_TRUE(fs::is_regular_file(report().parent_path() / src)) << src;
    cuts += src.find("/cut.png") != std::string::npos;
  }
  EXPECT_EQ(cuts, 6u);
}

// The report with a probe that, once the page has loaded, writes on <html> what a reader
// would see: the window's width, the page's width (more means a sideways scroll bar), the
// right edge of the key table, the pictures loaded, the charts, the errors seen.
std::string probed(const std::string& html) {
  const std::string listen =
      "<script>window.__errors=[];window.addEventListener('error',function(e){"
      "window.__errors.push(e.message||('cannot load '+(e.target&&e.target.src)));},true);"
      "</script>\n";
  const std::string probe =
      "<script>window.addEventListener('load',function(){var d=document.documentElement;"
      "var key=document.querySelector('table.key').getBoundingClientRect();"
      "var imgs=[].slice.call(document.images);"
      "d.setAttribute('data-window',window.innerWidth);"
      "d.setAttribute('data-page',d.scrollWidth);"
      "d.setAttribute('data-key-right',Math.ceil(key.right));"
      "d.setAttribute('data-images',imgs.length);"
      "d.setAttribute('data-loaded',imgs.filter(function(i){return i.complete&&"
      "i.naturalWidth>0;}).length);"
      "d.setAttribute('data-cut-top',Math.round(document.querySelector('figure.tets img')"
      ".getBoundingClientRect().top));"
      "d.setAttribute('data-svgs',document.querySelectorAll('svg').length);"
      "d.setAttribute('data-errors',window.__errors.length+':'+window.__errors.join('|'));"
      "});</script>\n";
  std::string out = html;
  out.insert(out.find("<head>") + 6, "\n" + listen);
  out.insert(out.rfind("</body>"), probe);
  return out;
}

std::map<std::string, std::string> probe_values(const std::string& dom) {
  std::map<std::string, std::string> values;
  const size_t end = dom.find('>', dom.find("<html"));
  const std::string tag = dom.substr(0, end);
  const std::regex attribute("data-([a-z-]+)=\"([^\"]*)\"");
  for (std::sregex_iterator it(tag.begin(), tag.end(), attribute), stop; it != stop; ++it)
    values[(*it)[1]] = (*it)[2];
  return values;
}

TEST_F(ReportBrowser, HeadlessChromiumShowsTheKeyColumnsChartsAndTetViewWithoutErrors) {
  const std::string browser = chromium();
  if (browser.empty())
    GTEST_SKIP() << "Chromium is not installed (Debian package chromium; or VOROSEAL_CHROMIUM)";
  ASSERT_EQ(run_->exit_code, 0) << run_->out;
  const fs::path probe = report().parent_path() / "probe.html";
  std::ofstream(probe) << probed(read_text(report()));
  const std::string window =
      "--window-size=" + std::to_string(kWindowWidth) + "," + std::to_string(kWindowHeight);
  // Root needs --no-sandbox; a profile of its own keeps runs apart.
  const std::string common = "timeout 120 '" + browser +
                             "' --headless --no-sandbox --disable-gpu --hide-scrollbars "
                             "--user-data-dir='" +
                             (*dir_ / "profile").string() + "' " + window +
                             " --virtual-time-budget=10000 --enable-logging=stderr --v=0 ";
  const Result dom = shell(common + "--dump-dom 'file://" + probe.string() + "' 2>'" +
                           (*dir_ / "chromium.log").string() + "'");
  ASSERT_EQ(dom.exit_code, 0) << read_text(*dir_ / "chromium.log");
  const std::map<std::string, std::string> v = probe_values(dom.out);
  ASSERT_TRUE(v.count("window")) << "the probe did not run:\n" << dom.out.substr(0, 2000);
  const std::string log = read_text(*dir_ / "chromium.log");
  EXPECT_EQ(v.at("errors"), "0:") << log;
  EXPECT_EQ(log.find("Uncaught"), std::string::npos) << log;
  EXPECT_EQ(std::stoi(v.at("window")), kWindowWidth);
  EXPECT_LE(std::stoi(v.at("page")), kWindowWidth) << "the page scrolls sideways";
  EXPECT_LE(std::stoi(v.at("key-right")), kWindowWidth) << "key columns off screen";
  EXPECT_EQ(v.at("loaded"), v.at("images"));
  EXPECT_EQ(std::stoi(v.at("images")), 12);
  EXPECT_GE(std::stoi(v.at("svgs")), 5 + 6 * 3);
  EXPECT_LT(std::stoi(v.at("cut-top")), kWindowHeight) << "the first tet view is below the fold";

  // The screenshot of the report itself.
  const char* keep = std::getenv("VOROSEAL_REPORT_SHOT");
  const fs::path shot = keep ? fs::path(keep) : *dir_ / "shot.png";
  fs::remove(shot);
  const Result taken = shell(common + "--screenshot='" + shot.string() + "' 'file://" +
                             report().string() + "' 2>/dev/null");
  ASSERT_EQ(taken.exit_code, 0);
  const std::string png = read_text(shot);
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  const auto be32 = [&](size_t at) {
    return (unsigned(uint8_t(png[at])) << 24) | (unsigned(uint8_t(png[at + 1])) << 16) |
           (unsigned(uint8_t(png[at + 2])) << 8) | unsigned(uint8_t(png[at + 3]));
  };
  EXPECT_EQ(be32(16), unsigned(kWindowWidth));
  EXPECT_EQ(be32(20), unsigned(kWindowHeight));
}

}  // namespace
}  // namespace voroseal
