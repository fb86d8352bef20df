// The methods of one `solve` command line: every method's flags declared once on the command,
// and after parsing the chosen method with its flags bound into its settings.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "src/method/MethodUnit.h"

namespace hemirad {

class MethodChoice {
 public:
  // One of every registered method, or of `methods` (tests add their own).
  MethodChoice();
  explicit MethodChoice(std::vector<std::unique_ptr<MethodUnit>> methods);
  std::vector<std::string> names() const;
  // Each flag a method binds that `solve` lacks, once, in the option table's order, showing the
  // default of the first method that binds it. Flags methods only accept are solve's to add.
  void declareFlags(CLI::App* solve) const;
  // The method called `name` with the flags given on `solve` bound; InputError for a given flag
  // that another method takes and this one does not.
  MethodUnit& choose(const std::string& name, const CLI::App& solve) const;
  // Every flag some method takes.
  std::vector<std::string> flagNames() const;

 private:
  std::vector<std::unique_ptr<MethodUnit>> methods_;
};

}  // namespace hemirad
