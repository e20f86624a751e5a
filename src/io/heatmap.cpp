#include "brdflut/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <utility>

#include "brdflut/error.h"
#include "brdflut/png.h"
#include "io/bitmap_font.h"

namespace brdflut {
namespace {

using Color = std::array<std::uint8_t, 3>;
constexpr Color kInk{0, 0, 0};

// Layout, in pixels. Text is drawn at an integer scale of the bitmap font.
constexpr int kScale = 2;
constexpr int kCharAdvance = font::kAdvance * kScale;      // 12
constexpr int kTextHeight = font::kGlyphHeight * kScale;   // 18, descenders included
constexpr int kCapHeight = font::kCapHeight * kScale;      // 14
constexpr int kPlotTarget = 512;  // the longest an axis of cells is drawn
constexpr int kMargin = 16;
constexpr int kTickLength = 6;
constexpr int kTickGap = 6;       // between a tick and its label
constexpr int kLabelGap = 8;      // between tick labels and an axis label
constexpr int kColorbarGap = 28;  // between the plot and the colour bar
constexpr int kColorbarWidth = 20;
constexpr int kLegendGap = 14;
constexpr int kLegendLine = 24;
constexpr int kSwatch = 14;
constexpr int kOutline = 2;  // thickness of the highlight outline

int text_width(const std::string& s) {
    return s.empty() ? 0 : static_cast<int>(s.size()) * kCharAdvance - kScale;
}

std::string format_number(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

// Pixels along an axis of n cells.
int axis_pixels(int n) { return n <= kPlotTarget ? n * (kPlotTarget / n) : kPlotTarget; }

// Fraction of the plot edge (0 at the start, 1 at the end) where parameter
// value v of the axis lies: cell i covers [i/n, (i+1)/n] with its value at
// the centre, so for `endpoints` placement u = 0 and 1 are half a cell in.
double plot_fraction(const Axis& a, double v) {
    if (a.placement == Placement::zero_then_endpoints || a.placement == Placement::split_endpoints)
        return (a.position_of_value(v) + 0.5) / a.count;
    const double u = a.u_of_value(v);
    if (a.placement == Placement::center) return u;
    return (u * (a.count - 1) + 0.5) / a.count;
}

struct Tick {
    double value;
    double fraction;  // along the plot edge, see plot_fraction
};

// Round values within the axis range: multiples of 1, 2 or 5 times a power
// of ten (about five of them), or powers of ten for a log axis spanning
// more than a decade.
std::vector<Tick> axis_ticks(const Axis& a) {
    std::vector<Tick> ticks;
    const double lo = a.min, hi = a.max;
    if (a.warp == Warp::log && hi / lo >= 10.0) {
        for (double e = std::ceil(std::log10(lo) - 1e-9); e <= std::floor(std::log10(hi) + 1e-9); e += 1.0) {
            const double v = std::pow(10.0, e);
            ticks.push_back({v, plot_fraction(a, std::clamp(v, lo, hi))});
        }
        return ticks;
    }
    const double raw = (hi - lo) / 5.0;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = 10.0 * mag;
    for (const double m : {1.0, 2.0, 5.0})
        if (m * mag >= raw) {
            step = m * mag;
            break;
        }
    const double k0 = std::ceil(lo / step - 1e-9), k1 = std::floor(hi / step + 1e-9);
    // A range tiny beside its magnitude (k beyond 2^53) gets no ticks.
    if (!(k1 - k0 >= 0.0 && k1 - k0 <= 20.0)) return ticks;
    for (int m = 0; m <= static_cast<int>(k1 - k0); ++m) {
        double v = (k0 + m) * step;
        if (std::fabs(v) < 1e-9 * step) v = 0.0;
        ticks.push_back({v, plot_fraction(a, std::clamp(v, lo, hi))});
    }
    return ticks;
}


struct PlacedTick {
    int pos;  // pixel column (x axis) or row (y axis) relative to the plot
    std::string label;
    bool labelled;
};

// The ticks of an axis drawn over `pixels` pixels. Every stride-th tick is
// labelled, with the smallest stride that keeps labels apart; the others get
// a short unlabelled mark.
std::vector<PlacedTick> place_ticks(const Axis& a, int pixels, bool vertical) {
    // Labels with 6 significant digits, or more until they differ; none if
    // even 17 digits cannot tell them apart.
    const std::vector<Tick> values = axis_ticks(a);
    std::vector<PlacedTick> ticks;
    for (int digits = 6; digits <= 17; ++digits) {
        ticks.clear();
        std::set<std::string> distinct;
        for (const Tick& t : values) {
            const int offset = static_cast<int>(std::lround(t.fraction * pixels));
            ticks.push_back({vertical ? pixels - offset : offset, format_number(t.value, digits), false});
            distinct.insert(ticks.back().label);
        }
        if (distinct.size() == ticks.size()) break;
        if (digits == 17) return {};
    }
    // Extent of a label along the axis, and the gap wanted between labels.
    auto extent = [&](const PlacedTick& t) {
        const int start = vertical ? t.pos - kCapHeight / 2 : t.pos - text_width(t.label) / 2;
        return std::pair{start, start + (vertical ? kTextHeight : text_width(t.label))};
    };
    const int gap = vertical ? 6 : kCharAdvance;
    const std::size_t n = ticks.size();
    for (std::size_t stride = 1; stride <= std::max<std::size_t>(n, 1); ++stride) {
        bool fits = true;
        for (std::size_t k = stride; k < n && fits; k += stride) {
            const auto [a0, a1] = extent(ticks[k - stride]);
            const auto [b0, b1] = extent(ticks[k]);
            fits = std::max(a0, b0) - std::min(a1, b1) >= gap;
        }
        if (!fits) continue;
        for (std::size_t k = 0; k < n; k += stride) ticks[k].labelled = true;
        break;
    }
    return ticks;
}

// Top of a label rotated along an axis of `pixels` pixels: centred on it, or
// flush with its bottom when longer, so that it never reaches the text under
// the plot.
int rotated_label_top(const std::string& s, int pixels) {
    const int len = text_width(s);
    return len <= pixels ? (pixels - len) / 2 : pixels - len;
}

struct TextItem {
    std::string text;
    int x, y;       // top-left corner of the text box
    bool vertical;  // rotated a quarter turn anticlockwise (reads bottom to top)
    int width() const { return vertical ? kTextHeight : text_width(text); }
    int height() const { return vertical ? text_width(text) : kTextHeight; }
};

struct Box {
    int x0 = std::numeric_limits<int>::max(), y0 = std::numeric_limits<int>::max();
    int x1 = std::numeric_limits<int>::min(), y1 = std::numeric_limits<int>::min();
    void add(int x, int y, int w, int h) {
        x0 = std::min(x0, x);
        y0 = std::min(y0, y);
        x1 = std::max(x1, x + w);
        y1 = std::max(y1, y + h);
    }
};

class Canvas {
public:
    Canvas(int width, int height) : w_(width), h_(height), rgb_(static_cast<std::size_t>(width) * height * 3, 255) {}

    void set(int x, int y, Color c) {
        if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
        const std::size_t k = (static_cast<std::size_t>(y) * w_ + x) * 3;
        rgb_[k] = c[0];
        rgb_[k + 1] = c[1];
        rgb_[k + 2] = c[2];
    }
    void fill(int x, int y, int w, int h, Color c) {
        for (int yy = y; yy < y + h; ++yy)
            for (int xx = x; xx < x + w; ++xx) set(xx, yy, c);
    }
    // A frame of thickness t just outside the rectangle.
    void frame(int x, int y, int w, int h, int t, Color c) {
        fill(x - t, y - t, w + 2 * t, t, c);
        fill(x - t, y + h, w + 2 * t, t, c);
        fill(x - t, y, t, h, c);
        fill(x + w, y, t, h, c);
    }
    void text(const TextItem& item, Color c) {
        for (std::size_t k = 0; k < item.text.size(); ++k) {
            const char ch = item.text[k];
            for (int gy = 0; gy < font::kGlyphHeight; ++gy)
                for (int gx = 0; gx < font::kGlyphWidth; ++gx) {
                    if (!font::glyph_pixel(ch, gx, gy)) continue;
                    const int along = static_cast<int>(k) * kCharAdvance + gx * kScale;
                    if (item.vertical) {
                        // Glyph top to the left, text advancing upward from the bottom.
                        const int bottom = item.y + item.height();
                        fill(item.x + gy * kScale, bottom - along - kScale, kScale, kScale, c);
                    } else {
                        fill(item.x + along, item.y + gy * kScale, kScale, kScale, c);
                    }
                }
        }
    }
    int width() const { return w_; }
    int height() const { return h_; }
    std::vector<std::uint8_t> take() { return std::move(rgb_); }

private:
    int w_, h_;
    std::vector<std::uint8_t> rgb_;
};

void validate(const Heatmap& h) {
    auto check_axis = [](const char* which, const HeatmapAxis& a) {
        try {
            a.axis.validate();
        } catch (const Error& e) {
            throw Error(std::string("heatmap ") + which + " axis: " + e.what());
        }
    };
    check_axis("x", h.x);
    check_axis("y", h.y);
    const std::size_t n = static_cast<std::size_t>(h.x.axis.count) * static_cast<std::size_t>(h.y.axis.count);
    if (h.values.size() != n)
        throw Error("heatmap: " + std::to_string(h.values.size()) + " values given for " +
                    std::to_string(h.x.axis.count) + " x " + std::to_string(h.y.axis.count) +
                    " cells; expected " + std::to_string(n));
    for (const auto& [name, v] : {std::pair{"vmin", h.vmin}, std::pair{"vmax", h.vmax}})
        if (v && !std::isfinite(*v))
            throw Error(std::string("heatmap: ") + name + " " + format_number(*v, 17) + " is not finite");
    if (h.vmin && h.vmax && !(*h.vmin < *h.vmax))
        throw Error("heatmap: colour range vmin " + format_number(*h.vmin, 17) + " to vmax " +
                    format_number(*h.vmax, 17) + " is empty; vmin must be less than vmax");
    if (h.highlight && !std::isfinite(h.highlight->threshold))
        throw Error("heatmap: highlight threshold " + format_number(h.highlight->threshold, 17) +
                    " is not finite");
}

}  // namespace

std::array<int, 2> HeatmapImage::cell_center(int i, int j) const {
    const int px = static_cast<int>((i + 0.5) * plot.width / nx);
    const int py = static_cast<int>((j + 0.5) * plot.height / ny);
    return {plot.x + px, plot.y + plot.height - 1 - py};
}

std::array<std::uint8_t, 3> HeatmapImage::pixel(int x, int y) const {
    const std::size_t k = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
    return {rgb[k], rgb[k + 1], rgb[k + 2]};
}

HeatmapImage render_heatmap(const Heatmap& h) {
    validate(h);
    const int nx = h.x.axis.count, ny = h.y.axis.count;

    // Data range and colour range.
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    std::size_t non_finite = 0;
    for (const double v : h.values) {
        if (!std::isfinite(v)) {
            ++non_finite;
            continue;
        }
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    const bool any_finite = lo <= hi;
    double vmin = h.vmin ? *h.vmin : (any_finite ? lo : 0.0);
    double vmax = h.vmax ? *h.vmax : (any_finite ? hi : 1.0);
    if (h.vmin && !h.vmax && !(vmax > vmin)) vmax = vmin + 1.0;
    if (h.vmax && !h.vmin && !(vmin < vmax)) vmin = vmax - 1.0;
    const bool flat = !(vmin < vmax);  // a constant field: every cell mid-colour

    // Everything is placed relative to the plot's top-left corner, then shifted.
    // Text cannot collide by construction: tick labels, the x label and the
    // legend lie in rows under the plot; the rotated labels lie in columns
    // left of the y tick labels and right of the colour bar labels, and never
    // below the plot; the title is above everything else.
    const int pw = axis_pixels(nx), ph = axis_pixels(ny);
    std::vector<TextItem> items;

    // y ticks (value increases upward; labels right-aligned) and x ticks.
    const std::vector<PlacedTick> y_ticks = place_ticks(h.y.axis, ph, true);
    const std::vector<PlacedTick> x_ticks = place_ticks(h.x.axis, pw, false);
    int y_tick_width = 0;
    for (const PlacedTick& t : y_ticks) {
        if (!t.labelled) continue;
        y_tick_width = std::max(y_tick_width, text_width(t.label));
        items.push_back({t.label, -kTickLength - kTickGap - text_width(t.label), t.pos - kCapHeight / 2, false});
    }
    for (const PlacedTick& t : x_ticks)
        if (t.labelled)
            items.push_back({t.label, t.pos - text_width(t.label) / 2, ph + kTickLength + kTickGap, false});
    const int x_label_top = ph + kTickLength + kTickGap + kTextHeight + kLabelGap;
    if (!h.x.label.empty())
        items.push_back({h.x.label, (pw - text_width(h.x.label)) / 2, x_label_top, false});
    if (!h.y.label.empty())
        items.push_back({h.y.label, -kTickLength - kTickGap - y_tick_width - kLabelGap - kTextHeight,
                         rotated_label_top(h.y.label, ph), true});

    // Colour bar with ticks at vmin, the middle and vmax.
    const int cb_x = pw + kColorbarGap;
    const int cb_label_x = cb_x + kColorbarWidth + kTickLength + kTickGap;
    std::vector<int> cb_tick_rows;
    int cb_tick_width = 0;
    {
        const double vals[3] = {vmax, 0.5 * (vmin + vmax), vmin};
        const int rows[3] = {0, ph / 2, ph};
        for (int k = 0; k < (flat ? 1 : 3); ++k) {
            const int row = flat ? ph / 2 : rows[k];
            const std::string s = format_number(vals[flat ? 2 : k], 4);
            cb_tick_rows.push_back(row);
            cb_tick_width = std::max(cb_tick_width, text_width(s));
            items.push_back({s, cb_label_x, row - kCapHeight / 2, false});
        }
    }
    if (!h.colorbar_label.empty())
        items.push_back({h.colorbar_label, cb_label_x + cb_tick_width + kLabelGap,
                         rotated_label_top(h.colorbar_label, ph), true});

    // Legend lines under the x label: the data range, non-finite cells, the highlight.
    struct LegendSwatch {
        int row;
        Color color;
        bool outline;
    };
    std::vector<LegendSwatch> swatches;
    int legend_top = x_label_top + (h.x.label.empty() ? 0 : kTextHeight) + kLegendGap;
    const int legend_text_x = kSwatch + 10;
    {
        std::string range = any_finite ? "data: min " + format_number(lo, 4) + ", max " + format_number(hi, 4)
                                       : "data: no finite value";
        items.push_back({range, legend_text_x, legend_top, false});
        legend_top += kLegendLine;
        if (non_finite > 0) {
            items.push_back({"grey: NaN or infinite (" + std::to_string(non_finite) +
                                 (non_finite == 1 ? " cell)" : " cells)"),
                             legend_text_x, legend_top, false});
            swatches.push_back({legend_top, kHeatmapNonFiniteColor, false});
            legend_top += kLegendLine;
        }
        if (h.highlight) {
            const std::string s = h.highlight->label.empty()
                                      ? "outline: value > " + format_number(h.highlight->threshold, 6)
                                      : h.highlight->label;
            items.push_back({s, legend_text_x, legend_top, false});
            swatches.push_back({legend_top, kHeatmapHighlightColor, true});
            legend_top += kLegendLine;
        }
    }

    // Bounding box of everything but the title, which is centred over it.
    Box box;
    box.add(-1, -1, pw + 2, ph + 2);
    box.add(cb_x - 1, -1, kColorbarWidth + 2, ph + 2);
    box.add(0, 0, kSwatch, legend_top);
    for (const TextItem& it : items) box.add(it.x, it.y, it.width(), it.height());
    if (!h.title.empty()) {
        const int len = text_width(h.title);
        const TextItem title{h.title, (box.x0 + box.x1 - len) / 2, box.y0 - kLegendGap - kTextHeight, false};
        items.push_back(title);
        box.add(title.x, title.y, title.width(), title.height());
    }
    const int dx = kMargin - box.x0, dy = kMargin - box.y0;
    Canvas canvas(box.x1 - box.x0 + 2 * kMargin, box.y1 - box.y0 + 2 * kMargin);

    HeatmapImage img;
    img.nx = nx;
    img.ny = ny;
    img.vmin = vmin;
    img.vmax = vmax;
    img.plot = {dx, dy, pw, ph};
    img.colorbar = {cb_x + dx, dy, kColorbarWidth, ph};

    // Cells: pixel column p shows cell floor(p n / pixels); y up.
    auto cell_of = [&](int px, int py) {
        const int i = static_cast<int>(static_cast<long long>(px) * nx / pw);
        const int j = static_cast<int>(static_cast<long long>(ph - 1 - py) * ny / ph);
        return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i);
    };
    auto color_of = [&](double v) -> Color {
        if (!std::isfinite(v)) return kHeatmapNonFiniteColor;
        return viridis(flat ? 0.5 : (v - vmin) / (vmax - vmin));
    };
    for (int py = 0; py < ph; ++py)
        for (int px = 0; px < pw; ++px) canvas.set(dx + px, dy + py, color_of(h.values[cell_of(px, py)]));
    if (h.highlight) {
        // Outline the cells above the threshold on their borders with cells that are not.
        const double t = h.highlight->threshold;
        auto above = [&](int px, int py) {
            const double v = h.values[cell_of(px, py)];
            return std::isfinite(v) && v > t;  // non-finite cells are grey, not outlined
        };
        for (int py = 0; py < ph; ++py)
            for (int px = 0; px < pw; ++px) {
                if (!above(px, py)) continue;
                bool edge = false;
                for (int d = 1; d <= kOutline && !edge; ++d)
                    for (const auto& [ox, oy] : {std::pair{d, 0}, std::pair{-d, 0}, std::pair{0, d}, std::pair{0, -d}}) {
                        const int qx = px + ox, qy = py + oy;
                        if (qx >= 0 && qy >= 0 && qx < pw && qy < ph && !above(qx, qy)) edge = true;
                    }
                if (edge) canvas.set(dx + px, dy + py, kHeatmapHighlightColor);
            }
    }
    canvas.frame(dx, dy, pw, ph, 1, kInk);

    // Colour ramp: bottom row vmin, top row vmax.
    for (int py = 0; py < ph; ++py) {
        const Color c = viridis((ph - 1 - py + 0.5) / ph);
        canvas.fill(img.colorbar.x, dy + py, kColorbarWidth, 1, c);
    }
    canvas.frame(img.colorbar.x, dy, kColorbarWidth, ph, 1, kInk);

    // Ticks: 2 pixels thick, centred on the tick position; those without a
    // label are half as long.
    for (const PlacedTick& t : y_ticks) {
        const int len = t.labelled ? kTickLength : kTickLength / 2;
        canvas.fill(dx - 1 - len, dy + t.pos - 1, len, 2, kInk);
    }
    for (const PlacedTick& t : x_ticks)
        canvas.fill(dx + t.pos - 1, dy + ph + 1, 2, t.labelled ? kTickLength : kTickLength / 2, kInk);
    for (const int py : cb_tick_rows)
        canvas.fill(img.colorbar.x + kColorbarWidth + 1, dy + py - 1, kTickLength, 2, kInk);

    for (const LegendSwatch& s : swatches) {
        const int x = dx, y = dy + s.row + (kCapHeight - kSwatch) / 2;
        if (s.outline) {
            canvas.frame(x + kOutline, y + kOutline, kSwatch - 2 * kOutline, kSwatch - 2 * kOutline, kOutline, s.color);
        } else {
            canvas.fill(x, y, kSwatch, kSwatch, s.color);
            canvas.frame(x, y, kSwatch, kSwatch, 1, kInk);
        }
    }

    for (TextItem it : items) {
        it.x += dx;
        it.y += dy;
        canvas.text(it, kInk);
        img.text.push_back({it.x, it.y, it.width(), it.height()});
    }

    img.width = canvas.width();
    img.height = canvas.height();
    img.rgb = canvas.take();
    return img;
}

void write_heatmap_png(const std::string& path, const Heatmap& h) {
    const HeatmapImage img = render_heatmap(h);
    PngText text;
    if (!h.title.empty()) text.push_back({"Title", h.title});
    text.push_back({"Software", "brdflut"});
    write_png_rgb8(path, img.width, img.height, img.rgb, text);
}

}  // namespace brdflut
