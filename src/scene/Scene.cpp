#include "src/scene/Scene.h"

#include <algorithm>
#include <limits>

namespace hemirad {

double luminance(const glm::dvec3& c) {
  return kLuminanceWeights[0] * c.x + kLuminanceWeights[1] * c.y + kLuminanceWeights[2] * c.z;
}

bool Scene::addPolygon(const Poly3& vertices, int material, int object) {
  glm::dvec3 n = newellNormal(vertices);
  double len = glm::length(n);
  if (!(len > 0)) return false;
  if (!propsAdded_) {
    mesh_.add_property(polygonProp_, "hemirad:polygon");
    mesh_.add_property(materialProp_, "hemirad:material");
    mesh_.add_property(objectProp_, "hemirad:object");
    propsAdded_ = true;
  }
  // Each polygon gets its own vertices: OBJ files are rarely manifold, and the radiosity
  // charts are per polygon anyway; OpenMesh then never rejects a face as non-manifold.
  std::vector<Mesh::VertexHandle> handles;
  for (auto& v : vertices) handles.push_back(mesh_.add_vertex(Mesh::Point(v.x, v.y, v.z)));
  Mesh::FaceHandle f = mesh_.add_face(handles);
  int id = int(polygons_.size());
  if (f.is_valid()) {
    mesh_.property(polygonProp_, f) = id;
    mesh_.property(materialProp_, f) = material;
    mesh_.property(objectProp_, f) = object;
  }
  polygons_.push_back(ScenePolygon{vertices, n / len, 0.5 * len, material, object});
  return true;
}

Scene sceneLike(const Scene& s) {
  Scene out;
  out.path = s.path, out.materials = s.materials, out.objects = s.objects, out.warnings = s.warnings;
  out.emissionKey = s.emissionKey, out.sources = s.sources, out.unitScale = s.unitScale, out.camera = s.camera;
  out.creases = s.creases;
  return out;
}

int Scene::addMaterial(Material m) {
  materials.push_back(std::move(m));
  return int(materials.size()) - 1;
}

int Scene::addObject(std::string name) {
  for (size_t i = 0; i < objects.size(); ++i)
    if (objects[i].name == name) return int(i);
  objects.push_back({std::move(name)});
  return int(objects.size()) - 1;
}

void Scene::rescale(double factor) {
  for (std::vector<ScenePolygon>* list : {&polygons_, &wholes})
    for (ScenePolygon& p : *list) {
      for (glm::dvec3& v : p.vertices) v *= factor;
      p.area *= factor * factor;
    }
  for (Mesh::VertexHandle v : mesh_.vertices()) mesh_.set_point(v, mesh_.point(v) * factor);
}

double Scene::totalArea() const {
  double a = 0;
  for (auto& p : polygons_) a += p.area;
  return a;
}

double Scene::emittedPower() const {
  double s = 0;
  for (auto& p : polygons_) s += luminance(materials[p.material].emission) * p.area;
  return s;
}

glm::dvec3 Scene::boundsMin() const {
  glm::dvec3 lo(std::numeric_limits<double>::max());
  for (auto& p : polygons_)
    for (auto& v : p.vertices) lo = glm::min(lo, v);
  return lo;
}

glm::dvec3 Scene::boundsMax() const {
  glm::dvec3 hi(std::numeric_limits<double>::lowest());
  for (auto& p : polygons_)
    for (auto& v : p.vertices) hi = glm::max(hi, v);
  return hi;
}

}  // namespace hemirad
