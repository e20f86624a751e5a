// The readers behind read_table_image() (formats.h), each over a file's
// bytes in memory; each throws brdflut::RuntimeError "cannot read 'NAME': ...".
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "brdflut/exr.h"
#include "brdflut/formats.h"

namespace brdflut {

// NumPy .npy (npy.cpp).
ExrImage read_npy(const char* data, std::size_t size, const std::string& name, const ReadOptions& options);
// The initializer of options.array in a C, C++, GLSL, HLSL or JavaScript
// source (source_array.cpp).
ExrImage read_source_array(const char* data, std::size_t size, const std::string& name, const ReadOptions& options);

// The image `count` numbers form: `given` when given (its size must be
// count), else from `dims` (outermost first, as declared): the last is the
// channel count when `last_is_channels` (a vector element type) or when
// there are at least three and it is at most 4; then one dimension is W,
// two are H, W, three are D, H, W. Returns an empty string and sets
// `shape`, or says what is wrong ("holds N numbers but ...").
std::string resolve_shape(std::vector<long long> dims, long long count, const ArrayShape& given, ArrayShape& shape,
                          bool last_is_channels = false);

// Sizes `img` for `shape` (within image_limits.h) and names its channels;
// returns an empty string or what is wrong.
std::string shape_image(ExrImage& img, const ArrayShape& shape);
// Reorders img.pixels, read in file order, from planes (shape.planar) to
// interleaved channels; nothing for interleaved shapes.
void interleave_planes(ExrImage& img, const ArrayShape& shape);

}  // namespace brdflut
