#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>

#include "cpu/ExactFormFactor.h"
#include "cpu/Hemisphere.h"
#include "gl/Shader.h"
#include "gl/State.h"
#include "src/solver/ItemBuffer.h"
#include "src/solver/Projection.h"
#include "src/solver/ShaderContract.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {
// The C++ twin of hemisphere.glsl's item-buffer projection p: the point in [-1, 1]^2 of
// shooter-frame point `local` and its layer (a hemicube face, else 0).
glm::dvec2 twinProject(Projection p, const glm::dvec3& local, int& face) {
  face = 0;
  switch (p) {
    case Projection::Orthographic:
      return cpu::hemiProject(local);
    case Projection::Conformal:
      return cpu::conformalProject(local);
    case Projection::EqualArea:
      return cpu::equalAreaProject(local);
    case Projection::Hemicube:
      break;
  }
  face = cpu::cubeFaceOf(local);
  const glm::dvec3 f = cpu::cubeFace(local, face);
  return glm::dvec2(f) / f.z;
}

glm::dvec3 twinDirection(Projection p, const glm::dvec2& ndc, int face) {
  switch (p) {
    case Projection::Orthographic:
      return cpu::hemiDirection(ndc);
    case Projection::Conformal:
      return cpu::conformalDirection(ndc);
    case Projection::EqualArea:
      return cpu::equalAreaDirection(ndc);
    case Projection::Hemicube:
      break;
  }
  return cpu::cubeDirection(ndc, face);
}

// The radius each disc map puts a direction at angle theta from the normal (Projection.h).
double discRadius(Projection p, double theta) {
  if (p == Projection::Conformal) return std::tan(theta / 2);
  if (p == Projection::EqualArea) return std::sqrt(2.0) * std::sin(theta / 2);
  return std::sin(theta);
}
}  // namespace

TEST_CASE("Hemispherical projection puts the normal at the centre, theta at radius sin(theta), the horizon on the rim",
          "[cpu]") {
  const glm::dvec3 origin(1, 2, 3), n = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  glm::dvec3 t, b;
  cpu::shooterBasis(n, t, b);
  CHECK(glm::dot(t, b) == Approx(0).margin(1e-12));
  CHECK(glm::dot(t, n) == Approx(0).margin(1e-12));
  CHECK(glm::length(glm::cross(t, b) - n) == Approx(0).margin(1e-12));  // right-handed
  CHECK(glm::length(cpu::hemiProject(cpu::shooterLocal(origin + 5.0 * n, origin, n))) == Approx(0).margin(1e-12));
  for (double theta : {0.1, 0.5, 1.0, 1.4}) {
    for (double phi : {0.0, 1.0, 2.5, 4.0}) {
      glm::dvec3 dir = std::cos(theta) * n + std::sin(theta) * (std::cos(phi) * t + std::sin(phi) * b);
      glm::dvec2 p = cpu::hemiProject(cpu::shooterLocal(origin + 7.0 * dir, origin, n));
      CHECK(glm::length(p) == Approx(std::sin(theta)));
      CHECK(std::atan2(p.y, p.x) == Approx(std::remainder(phi, 2 * M_PI)).margin(1e-9));
    }
  }
  glm::dvec3 horizon = glm::normalize(t + b);
  CHECK(glm::length(cpu::hemiProject(cpu::shooterLocal(origin + horizon, origin, n))) == Approx(1.0));
}

TEST_CASE("Every item-buffer projection puts theta at its radius, keeps the azimuth, and its inverse undoes it",
          "[cpu]") {
  const glm::dvec3 origin(1, 2, 3), n = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  glm::dvec3 t, b;
  cpu::shooterBasis(n, t, b);
  for (Projection p : allProjections())
    for (double theta : {0.0, 0.1, 0.5, 1.0, 1.4, M_PI / 2})
      for (double phi : {0.0, 1.0, 2.5, 4.0}) {
        const glm::dvec3 dir = std::cos(theta) * n + std::sin(theta) * (std::cos(phi) * t + std::sin(phi) * b);
        const glm::dvec3 local = cpu::shooterLocal(origin + 7.0 * dir, origin, n);
        int face = 0;
        const glm::dvec2 q = twinProject(p, local, face);
        INFO(projectionName(p) << " theta " << theta << " phi " << phi);
        if (p != Projection::Hemicube) {
          CHECK(glm::length(q) == Approx(discRadius(p, theta)).margin(1e-12));
          if (theta > 0) CHECK(std::atan2(q.y, q.x) == Approx(std::remainder(phi, 2 * M_PI)).margin(1e-9));
        }
        CHECK(glm::length(glm::normalize(twinDirection(p, q, face)) - glm::normalize(local)) == Approx(0).margin(1e-9));
      }
  // The paraboloid map (Heidrich & Seidel 1998), (x, y) / (1 + z), is the conformal one.
  const glm::dvec3 u = glm::normalize(glm::dvec3(0.3, -0.4, 0.5));
  CHECK(glm::length(cpu::conformalProject(u) - glm::dvec2(u) / (1 + u.z)) == Approx(0).margin(1e-15));
  CHECK(parseProjection("paraboloid") == Projection::Conformal);
  CHECK(parseProjection("stereographic") == Projection::Orthographic);  // its old name, bitwise the same map
}

TEST_CASE("GLSL hemisphere maths equals its C++ mirror", "[gl]") {
  test::backend();
  // A compute shader runs hemisphere.glsl on test directions; the C++ mirror must agree.
  gl::Program p = computeProgram("hemisphere_probe.comp");
  std::vector<glm::vec4> in;
  for (int i = 0; i < 64; ++i) {
    double theta = 0.02 + 1.5 * i / 64.0, phi = 0.7 * i;
    in.push_back(glm::vec4(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta), 0));
  }
  const glm::vec3 n = glm::normalize(glm::vec3(-0.2f, 0.9f, 0.1f)), origin(3, -1, 2);
  gl::Buffer inBuf{std::span<const glm::vec4>(in)}, outBuf{in.size() * sizeof(glm::vec4)};
  inBuf.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_PROBE_IN);
  outBuf.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_PROBE_OUT);
  p.set("normal", n.x, n.y, n.z);
  p.set("origin", origin.x, origin.y, origin.z);
  p.use();
  gl::Program::dispatch(unsigned(in.size()));
  gl::barrier(gl::Barrier::BufferUpdate);
  std::vector<glm::vec4> out(in.size());
  outBuf.read(0, out.size() * sizeof(glm::vec4), out.data());
  for (size_t i = 0; i < in.size(); ++i) {
    glm::dvec3 t, b;
    cpu::shooterBasis(glm::dvec3(n), t, b);
    glm::dvec3 world =
        glm::dvec3(origin) + 4.0 * (double(in[i].x) * t + double(in[i].y) * b + double(in[i].z) * glm::dvec3(n));
    glm::dvec2 expect = cpu::hemiProject(cpu::shooterLocal(world, glm::dvec3(origin), glm::dvec3(n)));
    CHECK(out[i].x == Approx(expect.x).margin(1e-5));
    CHECK(out[i].y == Approx(expect.y).margin(1e-5));
    CHECK(out[i].z == Approx(cpu::discFormFactor(0.8, 0.6, 2.0, 0.5)).epsilon(1e-5));
  }
}

TEST_CASE("GLSL item-buffer projections (all four, the hemicube's faces included) equal their C++ twins", "[gl]") {
  test::backend();
  const Projection projection = GENERATE(from_range(allProjections()));
  INFO(projectionName(projection));
  gl::Program program = computeProgram("projection_probe.comp", itemBufferDefines(projection));
  // Directions over the whole hemisphere and a little below (what the clip plane cuts), and
  // item-buffer points inside and outside the disc, on every hemicube face.
  std::mt19937 rng(27);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<glm::vec4> dirs, points;
  for (int i = 0; i < 256; ++i) {
    const double theta = std::acos(0.475 + 0.525 * u(rng)), phi = M_PI * u(rng);  // cos theta in [-0.05, 1]
    dirs.push_back(glm::vec4(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta), 0));
    const int face = projection == Projection::Hemicube ? i % 5 : 0;
    points.push_back(glm::vec4(1.1 * u(rng), face ? 0.999 * std::abs(u(rng)) : 1.1 * u(rng), float(face), 0));
  }
  const glm::vec3 n = glm::normalize(glm::vec3(-0.2f, 0.9f, 0.1f)), origin(3, -1, 2);
  const float far = 20.0f;
  const int size = 128;
  gl::Buffer dirBuf{std::span<const glm::vec4>(dirs)}, pointBuf{std::span<const glm::vec4>(points)},
      outBuf{3 * dirs.size() * sizeof(glm::vec4)};
  dirBuf.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_PROBE_IN);
  pointBuf.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_PROBE_POINTS);
  outBuf.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_PROBE_OUT);
  program.set("normal", n.x, n.y, n.z);
  program.set("origin", origin.x, origin.y, origin.z);
  program.set("farDistance", far);
  program.set("size", size);
  program.use();
  gl::Program::dispatch(unsigned(dirs.size()));
  gl::barrier(gl::Barrier::BufferUpdate);
  std::vector<glm::vec4> out(3 * dirs.size());
  outBuf.read(0, out.size() * sizeof(glm::vec4), out.data());
  glm::dvec3 t, b;
  cpu::shooterBasis(glm::dvec3(n), t, b);
  int texelsChecked = 0;
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    const glm::dvec3 d(dirs[i]), o(origin);
    const glm::dvec3 nd(n), local = cpu::shooterLocal(o + 4.0 * (d.x * t + d.y * b + d.z * nd), o, nd);
    int face = 0;
    const glm::dvec2 q = twinProject(projection, local, face);
    const glm::dvec3 a = glm::abs(local);
    const bool faceTie = std::abs(local.z - std::max(a.x, a.y)) < 1e-4 || std::abs(a.x - a.y) < 1e-4;
    INFO("direction " << i << ": GLSL " << out[3 * i].x << ", " << out[3 * i].y << " face " << out[3 * i].w << "; C++ "
                      << q.x << ", " << q.y << " face " << face);
    if (projection == Projection::Hemicube && faceTie) continue;
    CHECK(out[3 * i].w == float(face));
    CHECK(out[3 * i].x == Approx(q.x).margin(2e-5));
    CHECK(out[3 * i].y == Approx(q.y).margin(2e-5));
    const double depth = projection == Projection::Hemicube ? 1e-6 * far / cpu::cubeFace(local, face).z
                                                            : 2 * glm::length(local) / far - 1;
    CHECK(out[3 * i].z == Approx(depth).epsilon(1e-4).margin(1e-6));
    // The texel, where the pixel edge is not within float rounding of the point.
    const glm::dvec2 pixel = glm::clamp((q * 0.5 + 0.5) * double(size), 0.0, size - 1e-9);
    const glm::dvec2 frac = pixel - glm::floor(pixel);
    if (glm::any(glm::lessThan(glm::min(frac, 1.0 - frac), glm::dvec2(1e-3)))) continue;
    ++texelsChecked;
    CHECK(out[3 * i + 1].x == float(std::floor(pixel.x)));
    CHECK(out[3 * i + 1].y == float(std::floor(pixel.y)));
  }
  CHECK(texelsChecked > 200);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::dvec3 expect = glm::normalize(twinDirection(projection, glm::dvec2(points[i]), int(points[i].z)));
    INFO("point " << i << " (" << points[i].x << ", " << points[i].y << ", face " << points[i].z << ")");
    CHECK(glm::length(glm::dvec3(out[3 * i + 2]) - expect) == Approx(0).margin(2e-5));
  }
}

TEST_CASE("A shader that fails to compile is reported with its file names and the driver's log", "[gl]") {
  test::backend();
  std::string dir = test::tempPath("shaders");
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/broken_probe.comp") << "#include \"hemisphere.glsl\"\nlayout(local_size_x = 1) in;\n"
                                               "void main() { float x = undefined_thing; }\n";
  setenv("HEMIRAD_SHADER_DIR", dir.c_str(), 1);
  try {
    computeProgram("broken_probe.comp");
    FAIL("the broken shader compiled");
  } catch (const gl::Error& e) {
    std::string what = e.what();
    CHECK_THAT(what, Catch::Contains("broken_probe.comp"));
    CHECK_THAT(what, Catch::Contains("1=hemisphere.glsl"));
    CHECK_THAT(what, Catch::Contains("undefined_thing"));  // the driver's log, naming the culprit
  }
  unsetenv("HEMIRAD_SHADER_DIR");
}

TEST_CASE("GLSL exact form factor (formfactor.glsl) equals cpu::pointToPolygon on random configurations", "[gl]") {
  test::backend();
  // Convex 3- to 8-gons of radius 1 at distances 0.3 to 100 (F from ~0.5 down to ~1e-5), some
  // straddling the receiver's horizon (clipped), some behind it or facing away (F = 0).
  gl::Program p = computeProgram("formfactor_kernel_probe.comp");
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> u(-1, 1);
  auto unit = [&] {
    glm::dvec3 d(u(rng), u(rng), u(rng));
    return glm::length(d) > 0.1 ? glm::normalize(d) : glm::dvec3(0, 0, 1);
  };
  const int cases = 256;
  std::vector<glm::vec4> in, shapes;
  std::vector<double> expect;
  for (int i = 0; i < cases; ++i) {
    const glm::dvec3 x = 10.0 * glm::dvec3(u(rng), u(rng), u(rng)), n = unit();
    const double distance = 0.3 * std::pow(330.0, 0.5 * (u(rng) + 1));
    const glm::dvec3 centre = x + distance * unit(), nf = glm::normalize(x - centre + 0.8 * distance * unit());
    glm::dvec3 a, b;
    cpu::shooterBasis(nf, a, b);
    cpu::Polygon poly;
    const int k = 3 + i % 6;
    for (int j = 0; j < k; ++j)
      poly.push_back(centre + std::cos(2 * M_PI * j / k) * a + std::sin(2 * M_PI * j / k) * b);
    // The GPU gets the inputs rounded to float: the reference takes the same rounded inputs.
    auto f = [](const glm::dvec3& d) { return glm::dvec3(glm::vec3(d)); };
    cpu::Polygon rounded;
    for (auto& v : poly) rounded.push_back(f(v));
    expect.push_back(cpu::pointToPolygon(f(x), f(n), rounded, f(nf)));
    in.push_back(glm::vec4(glm::vec3(x), 0));
    in.push_back(glm::vec4(glm::vec3(n), 0));
    in.push_back(glm::vec4(glm::vec3(nf), 0));
    shapes.push_back(glm::vec4(float(k), 0, 0, 0));  // formfactor.glsl's shape layout: count, then vertices
    for (int j = 0; j < kMaxShapeVertices; ++j)
      shapes.push_back(j < k ? glm::vec4(glm::vec3(poly[size_t(j)]), 1) : glm::vec4(0.0f));
  }
  gl::Buffer inBuf{std::span<const glm::vec4>(in)}, shapeBuf{std::span<const glm::vec4>(shapes)},
      outBuf{cases * sizeof(float)};
  inBuf.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_PROBE_IN);
  shapeBuf.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_SHOOTER_SHAPES);
  outBuf.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_PROBE_OUT);
  p.use();
  gl::Program::dispatch(unsigned(cases));
  gl::barrier(gl::Barrier::BufferUpdate);
  std::vector<float> out(cases);
  outBuf.read(0, out.size() * sizeof(float), out.data());
  int zero = 0;
  for (int i = 0; i < cases; ++i) {
    INFO("case " << i << ": GLSL " << out[size_t(i)] << ", C++ " << expect[size_t(i)]);
    // Float: 1e-4 relative, and a millionth of the hemisphere absolute (F sums contour terms of
    // order 1 for a near polygon, each rounded to ~1e-7 by float and GLSL's atan; measured < 6e-7).
    CHECK(std::abs(out[size_t(i)] - expect[size_t(i)]) <= 1e-4 * expect[size_t(i)] + 1e-6);
    zero += expect[size_t(i)] == 0;
  }
  INFO(zero << " cases with F = 0");
  CHECK(zero > 10);
  CHECK(zero < cases / 2);
}
