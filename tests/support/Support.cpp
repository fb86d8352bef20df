#include "tests/support/Support.h"

#include "cpu/ExactFormFactor.h"

#include "cpu/Hemisphere.h"
#include "src/output/Renderer.h"

#include <sys/wait.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace hemirad::test {

Poly3 rectangle(glm::dvec3 o, glm::dvec3 u, glm::dvec3 v, double w, double h) {
  return {o, o + u * w, o + u * w + v * h, o + v * h};
}

int material(Scene& scene, double rho, double emission) {
  return scene.addMaterial({"m" + std::to_string(scene.materials.size()), glm::dvec3(rho), glm::dvec3(emission)});
}

Scene cube(double rho, double E, int lampFace) {
  Scene s;
  int wall = material(s, rho, E), lamp = material(s, 0.0, 1.0), o = s.addObject("box");
  const glm::dvec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1), O(0.0);
  const Poly3 faces[6] = {rectangle(O, Z, X, 1, 1), rectangle(Y, X, Z, 1, 1),   // floor, ceiling
                          rectangle(O, X, Y, 1, 1), rectangle(Z, Y, X, 1, 1),   // z = 0, z = 1
                          rectangle(O, Y, Z, 1, 1), rectangle(X, Z, Y, 1, 1)};  // x = 0, x = 1
  for (int i = 0; i < 6; ++i) s.addPolygon(faces[i], i == lampFace ? lamp : wall, o);
  return s;
}

void addSphere(Scene& s, glm::dvec3 centre, double radius, int slices, int stacks, int material, int object,
               bool inward) {
  auto at = [&](int i, int j) {  // j = 0 the south pole
    const double phi = 2 * M_PI * i / slices, theta = M_PI * j / stacks;
    return centre +
           radius * glm::dvec3(std::sin(theta) * std::cos(phi), -std::cos(theta), std::sin(theta) * std::sin(phi));
  };
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      Poly3 f = j == 0            ? Poly3{at(i, 0), at(i + 1, 1), at(i, 1)}
                : j == stacks - 1 ? Poly3{at(i, j), at(i + 1, j), at(i, j + 1)}
                                  : Poly3{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
      if (!inward) std::reverse(f.begin(), f.end());
      s.addPolygon(f, material, object);
    }
}

void addCylinder(Scene& s, glm::dvec3 base, double radius, double height, int slices, int material, int object) {
  auto at = [&](int i, double y) {
    const double phi = 2 * M_PI * i / slices;
    return base + glm::dvec3(radius * std::cos(phi), y, radius * std::sin(phi));
  };
  for (int i = 0; i < slices; ++i)
    s.addPolygon({at(i + 1, 0), at(i, 0), at(i, height), at(i + 1, height)}, material, object);
}

gl::RenderBackend& backend() {
  static std::unique_ptr<gl::RenderBackend> b = [] {
    gl::BackendOptions o;
    const char* kind = std::getenv("HEMIRAD_TEST_BACKEND");
    o.kind = kind ? gl::parseBackendKind(kind) : gl::BackendKind::OSMesa;
    return gl::createBackend(o);
  }();
  return *b;
}

Solved solve(const Scene& scene, double texelSize, const ProgressiveSettings& settings, const Camera* camera) {
  return solve(scene, buildAtlas(scene, texelSize), settings, camera);
}

Solved solve(const Scene& scene, Atlas atlas, const ProgressiveSettings& settings, const Camera* camera) {
  backend();
  Solved out;
  out.atlas = std::move(atlas);
  SolverState state(scene, out.atlas);
  ProgressiveSolver solver(state, settings);
  if (settings.importanceDriven()) solver.look(*camera, 1.0);
  while (!out.status.done) out.status = solver.advance(64);
  if (settings.importanceDriven()) out.direct = solver.directImportance();
  if (camera) out.view = Renderer(state).render(*camera, 128, 128, 1);
  out.B = state.readRadiosity();
  out.dB = state.readDeltaB();
  out.objects = objectRadiosity(scene, out.atlas, out.B);
  out.hash = radiosityHash(out.atlas, out.B);
  return out;
}

const ObjectRadiosity& object(const Solved& s, const std::string& name) {
  for (const auto& o : s.objects)
    if (o.name == name) return o;
  throw std::runtime_error("no object " + name);
}

double discRowSum(const Scene& scene, const Atlas& a, size_t s) {
  glm::dvec3 ps(a.positionArea[s]), ns = scene.polygons()[a.polygonOf[s]].normal;
  double As = a.positionArea[s].w, sum = 0;
  for (size_t j = 0; j < a.polygonOf.size(); ++j) {
    if (a.polygonOf[j] == kNoPolygon || a.chartAt(j) == a.chartAt(s)) continue;
    glm::dvec3 d = glm::dvec3(a.positionArea[j]) - ps;
    double r2 = glm::dot(d, d);
    glm::dvec3 w = d / std::sqrt(r2);
    sum += cpu::discFormFactor(glm::dot(ns, w), -glm::dot(scene.polygons()[a.polygonOf[j]].normal, w), r2, As) *
           a.positionArea[j].w / As;
  }
  return sum;
}

double exactRowSum(const Scene& scene, const Atlas& a, size_t s) {
  const std::vector<Poly3> shape = a.elementShape(scene, int(s % a.width), int(s / a.width));
  double sum = 0;
  for (size_t j = 0; j < a.polygonOf.size(); ++j) {
    if (a.polygonOf[j] == kNoPolygon || a.chartAt(j) == a.chartAt(s)) continue;
    const glm::dvec3 nj = glm::normalize(glm::dvec3(a.normalOf[j]));
    for (const Poly3& piece : shape)
      sum += cpu::pointToPolygon(glm::dvec3(a.positionArea[j]), nj, piece, glm::normalize(newellNormal(piece))) *
             a.positionArea[j].w;
  }
  return sum / a.positionArea[s].w;
}

double meanExactRowSum(const Scene& scene, const Atlas& a) {
  double sigma = 0, area = 0;
  for (std::size_t t = 0; t < a.polygonOf.size(); ++t)
    if (a.polygonOf[t] != kNoPolygon)
      sigma += exactRowSum(scene, a, t) * a.positionArea[t].w, area += a.positionArea[t].w;
  return sigma / area;
}

double meanDiscRowSum(const Scene& scene, const Atlas& a) {
  double sigma = 0, area = 0;
  for (std::size_t t = 0; t < a.polygonOf.size(); ++t)
    if (a.polygonOf[t] != kNoPolygon)
      sigma += discRowSum(scene, a, t) * a.positionArea[t].w, area += a.positionArea[t].w;
  return sigma / area;
}

Run hemirad(const std::string& args, const std::string& env) { return shell(env + " " + HEMIRAD_BINARY + " " + args); }

Run shell(const std::string& script) {
  std::string cmd = "HEMIRAD='" + std::string(HEMIRAD_BINARY) + "'; { " + script + "\n} 2>&1";
  Run run;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) run.output.append(buf.data(), n);
  int status = pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

std::string sourcePath(const std::string& relative) { return std::string(HEMIRAD_SOURCE_DIR) + "/" + relative; }

std::string tempPath(const std::string& name) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("hemirad-tests-" + std::to_string(getpid()));
  fs::create_directories(dir);
  fs::path p = dir / name;
  fs::remove_all(p);
  return p.string();
}

}  // namespace hemirad::test
