// The writers behind write_table() (include/brdflut/formats.h). Each checks
// the table (io/table_checks.h) before creating any file and writes atomically.
#pragma once

#include <string>

#include "brdflut/table.h"

namespace brdflut {

void write_dds(const std::string& path, const Table& table, Storage storage);
void write_ktx2(const std::string& path, const Table& table, Storage storage);
void write_cpp_header(const std::string& path, const Table& table, PixelType pixel);
// An 8- or 16-bit PNG of unorm8, unorm16 or rgbd samples.
void write_png_table(const std::string& path, const Table& table, Storage storage);

// Channels stored by dds and ktx2: 1, 2 or 4 (a 3-channel table gets A = 1).
inline int gpu_stored_channels(int table_channels) { return table_channels == 3 ? 4 : table_channels; }

}  // namespace brdflut
