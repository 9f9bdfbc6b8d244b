// Results are written atomically: to a temporary file beside the target, flushed and synced,
// then renamed over it. A crash leaves either the old file or the complete new one, never half.
#pragma once

#include <filesystem>
#include <string>

namespace mrsph {

void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace mrsph
