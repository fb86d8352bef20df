#include "src/solver/Checkpoint.h"

#include <fcntl.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/base/Hash.h"
#include "src/solver/Presets.h"
#include "src/solver/Projection.h"

namespace hemirad {

namespace {

// Layout: magic, then length-prefixed sections (identity JSON, B, dB, solver state), then an
// FNV-1a 64 checksum of everything before it, so truncation or corruption is detected.
constexpr char kMagic[] = "hemirad checkpoint 1\n";

void appendSection(std::string& out, const void* data, std::uint64_t bytes) {
  out.append(reinterpret_cast<const char*>(&bytes), sizeof bytes);
  out.append(static_cast<const char*>(data), bytes);
}

// Test hook (tests/CheckpointTest.cpp): HEMIRAD_TEST_KILL_IN_CHECKPOINT=N kills the process
// with SIGKILL half way through writing its N-th checkpoint, as a power cut or `kill -9` would.
bool killHere() {
  static int written = 0;
  const char* n = std::getenv("HEMIRAD_TEST_KILL_IN_CHECKPOINT");
  return n && ++written == std::atoi(n);
}

void writeAll(int fd, const char* data, std::size_t n, const std::string& path) {
  while (n > 0) {
    ssize_t k = ::write(fd, data, n);
    if (k < 0) fail("{}: write failed: {}", path, std::strerror(errno));
    data += k, n -= std::size_t(k);
  }
}

}  // namespace

std::uint64_t sceneHash(const Scene& scene) {
  Fnv1a f;
  for (const ScenePolygon& p : scene.polygons()) {
    for (const glm::dvec3& v : p.vertices) f.add(v);
    f.add(p.material), f.add(p.object);
  }
  for (const Material& m : scene.materials) f.add(m.reflectance), f.add(m.emission);
  return f.value();
}

void writeCheckpoint(const std::string& path, const Checkpoint& c) {
  nlohmann::json header = c.identity;
  header["shots"] = c.shots;
  std::string bytes = kMagic, text = header.dump();
  appendSection(bytes, text.data(), text.size());
  appendSection(bytes, c.radiosity.data(), c.radiosity.size() * sizeof(glm::vec4));
  appendSection(bytes, c.deltaB.data(), c.deltaB.size() * sizeof(glm::vec4));
  appendSection(bytes, c.solver.data(), c.solver.size());
  Fnv1a f;
  f.add(bytes.data(), bytes.size());
  const std::uint64_t sum = f.value();
  bytes.append(reinterpret_cast<const char*>(&sum), sizeof sum);
  writeAtomically(path, [&](const std::string& tmp) {
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) fail("{}: cannot write: {}", path, std::strerror(errno));
    try {
      if (killHere()) {
        writeAll(fd, bytes.data(), bytes.size() / 2, path);
        std::raise(SIGKILL);
      }
      writeAll(fd, bytes.data(), bytes.size(), path);
      if (::fsync(fd) != 0) fail("{}: fsync failed: {}", path, std::strerror(errno));
    } catch (...) {
      ::close(fd);
      throw;
    }
    ::close(fd);
  });
}

Checkpoint readCheckpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("--resume {}: cannot be read", path);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t magic = sizeof kMagic - 1;
  if (bytes.size() < magic + sizeof(std::uint64_t) || bytes.compare(0, magic, kMagic) != 0)
    fail("--resume {}: not a hemirad checkpoint", path);
  std::uint64_t stored;
  std::memcpy(&stored, bytes.data() + bytes.size() - sizeof stored, sizeof stored);
  Fnv1a f;
  f.add(bytes.data(), bytes.size() - sizeof stored);
  if (f.value() != stored) fail("--resume {}: checkpoint is truncated or corrupt (checksum mismatch)", path);

  std::size_t at = magic, end = bytes.size() - sizeof stored;
  auto section = [&](auto& out) {
    std::uint64_t n;
    if (end - at < sizeof n) fail("--resume {}: checkpoint is truncated", path);
    std::memcpy(&n, bytes.data() + at, sizeof n);
    at += sizeof n;
    if (n > end - at || n % sizeof(out[0]) != 0) fail("--resume {}: checkpoint is corrupt", path);
    out.resize(n / sizeof(out[0]));
    std::memcpy(out.data(), bytes.data() + at, n);
    at += n;
  };
  std::string text;
  Checkpoint c;
  section(text);
  section(c.radiosity);
  section(c.deltaB);
  section(c.solver);
  try {
    c.identity = nlohmann::json::parse(text);
    c.shots = c.identity.at("shots").get<unsigned>();
    c.identity.erase("shots");
  } catch (const nlohmann::json::exception& e) {
    fail("--resume {}: checkpoint header is corrupt: {}", path, e.what());
  }
  return c;
}

namespace {
// A checkpoint written before the projections were renamed says "stereographic" for what is now
// "orthographic": the same map, bitwise, so it must still resume.
nlohmann::json canonicalProjection(nlohmann::json identity) {
  auto it = identity.find("projection");
  if (it != identity.end() && it->is_string()) {
    try {
      *it = projectionName(parseProjection(it->get<std::string>()));
    } catch (const InputError&) {  // an unknown name: compared as written, and refused below
    }
  }
  return identity;
}
}  // namespace

void checkResumable(const std::string& path, const nlohmann::json& savedAsWritten, const nlohmann::json& current) {
  const nlohmann::json saved = canonicalProjection(savedAsWritten);
  if (saved.value("scene_hash", "") != current.value("scene_hash", ""))
    fail("--resume {}: the checkpoint was made for another scene (scene hash {}, this scene {})", path,
         saved.value("scene_hash", "(none)"), current.value("scene_hash", "(none)"));
  for (const auto& [key, value] : current.items()) {
    auto it = saved.find(key);
    if (it == saved.end() || *it != value)
      fail(
          "--resume {}: the checkpoint was made with {} = {}, this run has {}; resume with the same scene and "
          "parameters{}",
          path, key, it == saved.end() ? "(none)" : it->dump(), value.dump(),
          key == "refine_near" && it != saved.end() && it->is_number()
              ? fmt::format(" (--refine-near auto refines from --converge {:g}, within {:g} block sides under "
                            "--final-gather near: give --refine-near {:g} to go on as it began)",
                            kRefineFrom, kGatherRefineNear, it->get<double>())
              : "");
  }
}

}  // namespace hemirad
