// Heatmaps of a quantity over a two-axis parameter grid (for example the
// albedo E(mu_o, alpha) of a model, or the error of a table), drawn with the
// viridis colour map, a colour bar, ticks, axis labels and a title, and
// written as 8-bit PNG.
//
// Picture conventions: x increases to the right and y increases UPWARD (row 0
// of the data, the first value of the y axis, is the bottom row of cells).
// Each cell is an equal block of pixels (nearest neighbour); an axis of n
// cells spans n * floor(512 / n) pixels, or 512 pixels when n > 512, in which
// case pixel p shows cell floor(p n / 512) and some cells are not shown.
// Cells whose value is NaN or infinite are drawn grey and the legend says so.
// Text is printable ASCII drawn with a built-in bitmap font; other characters
// are drawn as '?'.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "brdflut/axis.h"

namespace brdflut {

struct HeatmapAxis {
    std::string label;  // printed beside the axis, e.g. "cos_theta = mu_o"
    // Maps cell index to parameter value (placement and warp as for tables);
    // axis.count is the number of cells along this axis. Ticks are placed at
    // round parameter values through this mapping, so a warped axis (square,
    // log) is labelled correctly.
    Axis axis;
};

struct HeatmapHighlight {
    // Finite cells whose value is > threshold get an outline drawn inside
    // them along their borders with the other cells.
    double threshold = 1.0;
    std::string label;       // legend text; empty: "outline: value > <threshold>"
};

struct Heatmap {
    std::string title;
    HeatmapAxis x, y;
    // x.axis.count * y.axis.count values, row-major: values[j * nx + i] is the
    // cell at x index i and y index j.
    std::vector<double> values;
    std::string colorbar_label;
    // Colour range; by default the smallest and largest finite value. Values
    // outside the range take the colour of the nearer end.
    std::optional<double> vmin, vmax;
    std::optional<HeatmapHighlight> highlight;
};

struct PixelRect {
    int x = 0, y = 0, width = 0, height = 0;  // top-left corner and size, in pixels
};

// A rendered heatmap and where its parts are.
struct HeatmapImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;  // width * height * 3 bytes, row 0 at the top
    PixelRect plot;                 // the cells (inside the frame)
    PixelRect colorbar;             // the colour ramp (inside its frame)
    std::vector<PixelRect> text;    // every string drawn: title, labels, ticks, legend
    int nx = 0, ny = 0;             // cells along x and y
    double vmin = 0.0, vmax = 1.0;  // the colour range used

    // The pixel at the centre of cell (i, j) (y up, so j = 0 is near the bottom).
    std::array<int, 2> cell_center(int i, int j) const;
    std::array<std::uint8_t, 3> pixel(int x, int y) const;
};

// Viridis colour of t in [0, 1] (clamped): entry floor(256 t) of the
// 256-entry table, entry 255 for t = 1.
std::array<std::uint8_t, 3> viridis(double t);

// Colour of cells whose value is NaN or infinite.
inline constexpr std::array<std::uint8_t, 3> kHeatmapNonFiniteColor{128, 128, 128};
// Colour of the highlight outline.
inline constexpr std::array<std::uint8_t, 3> kHeatmapHighlightColor{255, 0, 255};

// Throws brdflut::Error for bad input: axis counts below 1 or whose product
// differs from values.size(), a malformed axis, a non-finite or empty colour
// range (vmin >= vmax), a non-finite highlight threshold.
HeatmapImage render_heatmap(const Heatmap& h);

// Renders and writes an 8-bit RGB PNG atomically (see write_png_rgb8); the
// title is stored as the PNG "Title" text. Throws brdflut::Error for bad
// input, brdflut::RuntimeError when the file cannot be written.
void write_heatmap_png(const std::string& path, const Heatmap& h);

}  // namespace brdflut
