#pragma once
// Checks that region files make exactly one image before `sdfc merge`
// writes anything: the same image, settings and AOVs in every part, every
// pixel in exactly one part. Errors name the part (file and number) at fault.
#include <sdfrt/region_file.hpp>

#include <string>
#include <vector>

namespace sdfc::cli {

struct PartInfo {
  std::string path;
  sdfrt::RegionHeader header;
};

// Throws std::invalid_argument with what is missing, overlapping or
// mismatched; returns nothing when the parts tile the image exactly.
void check_parts(const std::vector<PartInfo>& parts);

}  // namespace sdfc::cli
