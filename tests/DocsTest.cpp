// Links into the docs hold: every `NAME.md#anchor` written in the docs, the README or the code
// names a heading of that page (GitHub's anchors: lower case, punctuation dropped, spaces to
// hyphens). A renamed heading fails here, not in a reader's browser.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>

#include "tests/support/Support.h"

namespace fs = std::filesystem;

namespace {
std::string read(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// GitHub's anchor for a heading's text.
std::string slug(const std::string& heading) {
  std::string out;
  for (unsigned char c : heading) {
    if (std::isalnum(c) || c == '-' || c == '_')
      out += char(std::tolower(c));
    else if (c == ' ')
      out += '-';
  }
  return out;
}

std::set<std::string> anchors(const fs::path& page) {
  std::set<std::string> out;
  std::ifstream in(page);
  bool code = false;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("```")) code = !code;
    if (code || !line.starts_with("#")) continue;
    const std::size_t text = line.find_first_not_of('#');
    if (text != std::string::npos && line[text] == ' ') out.insert(slug(line.substr(text + 1)));
  }
  return out;
}
}  // namespace

TEST_CASE("Every NAME.md#anchor in the docs, the README and the code names a heading of that page", "[cpu]") {
  const fs::path root = hemirad::test::sourcePath(".");
  std::map<std::string, std::set<std::string>> pages;  // file name: its anchors
  for (const auto& e : fs::directory_iterator(root / "docs"))
    if (e.path().extension() == ".md") pages[e.path().filename().string()] = anchors(e.path());
  pages["README.md"] = anchors(root / "README.md");
  const std::regex link(R"(([A-Za-z0-9_]+\.md)#([A-Za-z0-9_-]+))");
  int checked = 0;
  for (const char* folder : {"docs", "src", "gl", "cpu", "shaders", "tests", "ci"})
    for (const auto& e : fs::recursive_directory_iterator(root / folder)) {
      if (!e.is_regular_file() || e.path().extension() == ".json" || e.path().extension() == ".html") continue;
      const std::string text = read(e.path());
      for (std::sregex_iterator m(text.begin(), text.end(), link), end; m != end; ++m) {
        const std::string page = (*m)[1], anchor = (*m)[2];
        if (!pages.count(page) || anchor == "section" || anchor == "anchor") continue;  // another repo's, or prose
        INFO(e.path().string() << ": " << page << "#" << anchor);
        CHECK(pages[page].count(anchor) == 1);
        ++checked;
      }
    }
  CHECK(checked > 20);
}

TEST_CASE("No test name holds a semicolon, which ctest's discovery splits into two tests that both fail", "[cpu]") {
  const auto& tests = Catch::getRegistryHub().getTestCaseRegistry().getAllTests();
  CHECK(tests.size() > 100);
  for (const Catch::TestCase& t : tests) {
    INFO(t.name);
    CHECK(t.name.find(';') == std::string::npos);
  }
}

TEST_CASE("Every figure shipped in docs/ is drawn by the plotting code (matplotlib), none by hand", "[cpu]") {
  int figures = 0;
  for (const auto& f : fs::recursive_directory_iterator(test::sourcePath("docs"))) {
    if (f.path().extension() != ".svg") continue;
    ++figures;
    INFO(f.path());
    CHECK(read(f.path()).find("matplotlib.axis") != std::string::npos);  // its axes' ids
  }
  CHECK(figures > 0);
}
