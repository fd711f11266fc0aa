#include "check_registry.h"

#include <chrono>
#include <fmt/format.h>
#include <optional>
#include <regex>

#include "model/errors.h"
#include "outcome.h"

namespace gearbench::verification {

model::GearCase CheckContext::gear_case(const std::string& file) const {
  const auto json = model::read_json_file(case_path(file));
  model::ObjectReader root(json, "");
  return model::read_gear_case(root);
}

std::vector<double> scaled(std::vector<double> v, double factor) {
  for (auto& x : v) x *= factor;
  return v;
}

Registry& Registry::instance() {
  static Registry registry;
  return registry;
}

void Registry::add(CheckSpec check) { checks_.push_back(std::move(check)); }
void Registry::add(SectionSpec section) { sections_.push_back(std::move(section)); }

std::vector<const CheckSpec*> Registry::checks(Tier tier) const {
  std::vector<const CheckSpec*> out;
  for (const auto& c : checks_)
    if (tier == Tier::full || c.tier == Tier::fast) out.push_back(&c);
  return out;
}

std::vector<const SectionSpec*> Registry::sections(Tier tier) const {
  std::vector<const SectionSpec*> out;
  for (const auto& s : sections_)
    if (tier == Tier::full || s.tier == Tier::fast) out.push_back(&s);
  return out;
}

reports::CheckRecord run_check(const CheckSpec& check, const CheckContext& context) {
  reports::CheckRecord r;
  r.id = check.id;
  r.section = check.section;
  r.solver = check.solver;
  r.reference = check.reference;
  r.quantity = check.quantity;
  r.unit = check.unit;
  r.tolerance = check.tolerance;
  r.justification = check.justification;
  r.reproduction = check.recorded.has_value();
  r.recorded = check.recorded.value_or(0.0);
  r.recorded_tolerance = check.recorded_tolerance;
  const auto start = std::chrono::steady_clock::now();
  try {
    const CheckValue v = check.run(context);
    r.value = v.value;
    r.reference_value = v.reference;
    r.diagnostics = v.diagnostics;
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.outcome = classify(r);
  return r;
}

void build_section(const SectionSpec& section, const CheckContext& context, reports::Report& report) {
  build_section(section.id, [&](reports::Report& r) { section.add(context, r); }, report);
}

namespace {

/// The entries whose id matches `only` (all of them when it is empty).
template <class Spec>
std::vector<const Spec*> selected(std::vector<const Spec*> specs, const std::optional<std::regex>& only) {
  if (!only) return specs;
  std::erase_if(specs, [&](const Spec* s) { return !std::regex_search(s->id, *only); });
  return specs;
}

std::optional<std::regex> only_pattern(const std::string& only) {
  if (only.empty()) return std::nullopt;
  try {
    return std::regex(only);
  } catch (const std::regex_error& e) {
    throw InputError(fmt::format("--only \"{}\": not a regular expression ({})", only, e.what()));
  }
}

}  // namespace

reports::Report run_verification(Tier tier, const CheckContext& context,
                                 const std::function<void(const std::string&)>& progress, const std::string& only) {
  reports::Report report;
  report.tier = tier_name(tier);
  const auto pattern = only_pattern(only);
  const auto checks = selected(Registry::instance().checks(tier), pattern);
  const auto sections = selected(Registry::instance().sections(tier), pattern);
  if (pattern && checks.empty() && sections.empty())
    throw InputError(fmt::format("--only \"{}\": matches no check or section of the {} tier", only, tier_name(tier)));
  for (std::size_t i = 0; i < checks.size(); ++i) {
    report.checks.push_back(run_check(*checks[i], context));
    const auto& r = report.checks.back();
    progress(fmt::format("[{}/{}] {} ... {} ({:.2f} s)", i + 1, checks.size(), r.id,
                         reports::outcome_name(r.outcome), r.seconds));
  }
  for (const auto* section : sections) build_section(*section, context, report);
  return report;
}

Tier parse_tier(const std::string& name) {
  if (name == "fast") return Tier::fast;
  if (name == "full") return Tier::full;
  throw InputError(fmt::format("--tier = \"{}\": allowed values are fast, full", name));
}

std::string tier_name(Tier tier) { return tier == Tier::fast ? "fast" : "full"; }

}  // namespace gearbench::verification
