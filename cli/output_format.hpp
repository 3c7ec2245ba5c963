#pragma once
// What kind of file `-o` names: the extension decides (--format overrides
// it), and the options that depend on the kind (bit depth, quality, alpha)
// are checked against it before anything renders.
#include <string>
#include <vector>

namespace sdfc::cli {

enum class Format { Png, Exr, Pfm, Jpeg, Mp4, Mkv, Webm };

// The --format names, in the order help and errors list them.
const std::vector<std::string>& format_names();
const char* format_name(Format f);
bool is_video(Format f);

// From --format when given, else from the output name's extension.
// Throws std::invalid_argument naming the supported extensions.
Format output_format(const std::string& path, const std::string& forced);

// The options as given (0 / -1: not given) resolved for a format.
struct OutputChoices {
  int bit_depth = 0;  // PNG 8 (default) or 16; EXR 16 (half, default) or 32 (float)
  int quality = -1;   // JPEG 1-100 (default 90); video CRF (default per codec)
  bool alpha = false;
};
// Fills in the defaults; throws std::invalid_argument for a choice the
// format cannot take (JPEG alpha, 16-bit video, ...).
OutputChoices resolve_choices(Format f, OutputChoices given, bool aovs);

}  // namespace sdfc::cli
