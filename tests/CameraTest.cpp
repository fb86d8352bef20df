#include <catch2/catch.hpp>

#include "src/base/Error.h"
#include "src/scene/Camera.h"

using namespace hemirad;

TEST_CASE("Camera text sets the keys it names and keeps the others", "[cpu]") {
  Camera base;
  Camera c = parseCamera("eye=1,2,3,target=4,5,6,fov=30", base, "--camera");
  CHECK(c.eye == glm::dvec3(1, 2, 3));
  CHECK(c.target == glm::dvec3(4, 5, 6));
  CHECK(c.up == base.up);
  CHECK(c.fovY == Approx(30));
  Camera d = parseCamera("# sidecar\neye = 0 0 5\nup=0,0,1 target=0,1,0\n", base, "x.camera");
  CHECK(d.eye == glm::dvec3(0, 0, 5));
  CHECK(d.up == glm::dvec3(0, 0, 1));
}

TEST_CASE("Malformed camera text names the flag and the problem", "[cpu]") {
  Camera base;
  CHECK_THROWS_WITH(parseCamera("eye=1,2", base, "--camera"), Catch::Contains("--camera: 'eye' needs three numbers"));
  CHECK_THROWS_WITH(parseCamera("fov=200", base, "--camera"), Catch::Contains("fov"));
  CHECK_THROWS_WITH(parseCamera("pos=1,2,3", base, "--camera"), Catch::Contains("unknown camera key 'pos'"));
  CHECK_THROWS_WITH(parseCamera("eye=0,0,0,target=0,0,0", base, "--camera"), Catch::Contains("coincide"));
  CHECK_THROWS_AS(parseCamera("eye=1,x,3", base, "--camera"), InputError);
}
