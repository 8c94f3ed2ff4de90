// Pass plans: each method as data, a list of passes with their state.
#pragma once

#include <string>
#include <vector>

#include "fragment.h"

namespace zb {

struct PassPlan {
  std::string name;
  std::string source;       // where the method comes from
  std::string description;
  std::vector<PassState> passes;
};

// Every pass plan, in the order methods are listed.
const std::vector<PassPlan>& pass_plans();

// The plan called `name`, or nullptr.
const PassPlan* find_plan(const std::string& name);

// The name of the exact floating-point ground truth, which is not a pass plan.
constexpr const char* kReferenceMethod = "reference";

// Every method name: the pass plans, then the reference.
std::vector<std::string> method_names();

}  // namespace zb
