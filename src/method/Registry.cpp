#include "src/method/Registry.h"

namespace hemirad {

// Each in its folder under src/method/.
std::unique_ptr<MethodUnit> makeProgressiveMethod();
std::unique_ptr<MethodUnit> makeStochasticMethod();
std::unique_ptr<MethodUnit> makeInstantMethod();

std::vector<std::unique_ptr<MethodUnit>> makeMethods() {
  std::vector<std::unique_ptr<MethodUnit>> methods;
  for (auto make : {makeProgressiveMethod, makeStochasticMethod, makeInstantMethod}) methods.push_back(make());
  return methods;
}

std::vector<std::string> methodNames() {
  std::vector<std::string> names;
  for (const auto& m : makeMethods()) names.push_back(m->name());
  return names;
}

}  // namespace hemirad
