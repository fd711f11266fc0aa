#pragma once
// One result per name (an FE comparison or crack sweep), computed once per process and
// shared by the checks and report sections that read it: the FE solves are the cost.
#include <map>
#include <mutex>
#include <string>
#include <type_traits>

namespace gearbench::verification {

template <class F>
const std::invoke_result_t<F>& cached(const std::string& name, F&& make) {
  static std::mutex mutex;
  static std::map<std::string, std::invoke_result_t<F>> cache;
  const std::lock_guard lock(mutex);
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, make()).first;
  return it->second;
}

}  // namespace gearbench::verification
