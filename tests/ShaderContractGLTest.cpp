// The C++/GLSL contract (src/solver/ShaderContract.h): every shader compiles with its defines,
// binds by slot name only, with a name of the right kind, and no program holds two slots of a
// kind on one number. (ci/check-gl-boundary checks the C++ side: no literal slot in a binding call.)
#include <catch2/catch.hpp>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "gl/EmbeddedShaders.h"
#include "gl/Shader.h"
#include "src/solver/ShaderContract.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {
bool isStage(const std::string& name) {
  return name.ends_with(".comp") || name.ends_with(".vert") || name.ends_with(".frag");
}

// What each shader needs beyond the contract to compile at all.
gl::Defines extraDefines(const std::string& name) {
  if (name == "node_stats.comp") return {{"BLOCK_THREADS", "64"}};
  if (name == "gather.comp") return {{"GATHER_GROUP", "8"}};
  return {};
}

std::map<std::string, unsigned> slotNumbers() {
  std::map<std::string, unsigned> slots;
  for (const auto& [name, value] : contractDefines())
    if (name.starts_with("SSBO_") || name.starts_with("IMAGE_") || name.starts_with("SAMPLER_"))
      slots[name] = unsigned(std::stoul(value));
  return slots;
}

// The slot kind a declaration line needs: SSBO_ for a buffer block, IMAGE_ for an image, SAMPLER_
// for a sampler; "" for a line that declares none of them.
std::string kindOf(const std::string& line) {
  if (std::regex_search(line, std::regex(R"(\bbuffer\b)"))) return "SSBO_";
  if (std::regex_search(line, std::regex(R"(\bu?image\w+)"))) return "IMAGE_";
  if (std::regex_search(line, std::regex(R"(\bu?sampler\w+)"))) return "SAMPLER_";
  return "";
}

const std::regex kBinding(R"(binding\s*=\s*(\w+))");
}  // namespace

TEST_CASE("Every shader stage in shaders/ compiles with the contract's defines", "[gl]") {
  test::backend();
  int stages = 0;
  for (const std::string& name : gl::embeddedShaderNames()) {
    if (!isStage(name)) continue;
    INFO(name);
    gl::Defines defines = contractDefines();
    for (const auto& d : extraDefines(name)) defines.push_back(d);
    CHECK_NOTHROW(gl::checkCompiles(name, defines));
    ++stages;
  }
  CHECK(stages >= 30);  // the listing found the shaders
}

TEST_CASE("Shaders declare every binding by a contract slot name of the declaration's kind", "[cpu]") {
  const std::map<std::string, unsigned> slots = slotNumbers();
  int bindings = 0;
  for (const std::string& name : gl::embeddedShaderNames()) {
    std::istringstream in(*gl::embeddedShader(name));
    std::string line;
    for (int lineNo = 1; std::getline(in, line); ++lineNo) {
      const std::string code = line.substr(0, line.find("//"));
      std::smatch m;
      if (!std::regex_search(code, m, kBinding)) continue;
      INFO(name << ":" << lineNo << ": " << line);
      ++bindings;
      const std::string slot = m[1].str();
      CHECK(slots.count(slot) == 1);  // a name, not a number, and one of the table's
      const std::string kind = kindOf(code);
      CHECK(!kind.empty());
      CHECK(slot.starts_with(kind));
    }
  }
  CHECK(bindings >= 60);
}

TEST_CASE("No program declares two slots of one kind on the same binding number", "[cpu]") {
  const std::map<std::string, unsigned> slots = slotNumbers();
  int programs = 0;
  for (const std::string& name : gl::embeddedShaderNames()) {
    if (!isStage(name)) continue;
    ++programs;
    // The expanded source, includes and all (both sides of any #ifdef: a superset of a program).
    const std::string source = gl::shaderSource(name, contractDefines());
    std::set<std::string> names;
    for (std::sregex_iterator it(source.begin(), source.end(), kBinding), end; it != end; ++it)
      if (slots.count((*it)[1].str())) names.insert((*it)[1].str());
    std::map<std::pair<std::string, unsigned>, std::string> holder;  // (kind, number) -> slot
    for (const std::string& slot : names) {
      const std::string kind = slot.substr(0, slot.find('_') + 1);
      const auto [it, fresh] = holder.insert({{kind, slots.at(slot)}, slot});
      INFO(name << ": " << slot << " and " << it->second << " share binding " << slots.at(slot));
      CHECK(fresh);
    }
  }
  CHECK(programs >= 30);
}
