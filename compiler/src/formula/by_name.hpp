#pragma once
// The steps' and the presets' tables: sorted by name, looked up by name.
#include <algorithm>
#include <string_view>
#include <vector>

namespace sdfc::formula {

template <class T>
std::vector<const T*> sorted_by_name(std::vector<const T*> v) {
  std::sort(v.begin(), v.end(), [](const T* a, const T* b) { return a->name < b->name; });
  return v;
}

template <class T>
const T* find_by_name(const std::vector<const T*>& all, std::string_view name) {
  for (const T* d : all)
    if (d->name == name) return d;
  return nullptr;
}

}  // namespace sdfc::formula
