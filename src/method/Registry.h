// The radiosity methods `solve --method` runs: one line each in Registry.cpp.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "src/method/MethodUnit.h"

namespace hemirad {

// One of every registered method, in registry order, with its default settings.
std::vector<std::unique_ptr<MethodUnit>> makeMethods();
std::vector<std::string> methodNames();

}  // namespace hemirad
