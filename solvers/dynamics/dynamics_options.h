#pragma once
// The key "model" of a dynamics case, which picks the model; each model's Options declares its
// own keys (Spur6Options::table(), Herringbone12Options::table(), dynamics_options.cpp).
#include "model/option_table.h"

namespace gearbench::dynamics {

enum class ModelName { spur6, herringbone12 };

struct ModelChoice {
  ModelName model = ModelName::spur6;
  static const model::OptionTable<ModelChoice>& table();
};

}  // namespace gearbench::dynamics
