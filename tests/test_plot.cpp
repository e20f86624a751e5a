// PNG writers (8-bit RGB, 16-bit data) and heatmap plots, read back with libpng.
#include <gtest/gtest.h>

#include <png.h>

#include <cmath>
#include <csetjmp>
#include <filesystem>
#include <limits>
#include <map>
#include <set>

#include "brdflut/error.h"
#include "brdflut/plot.h"
#include "brdflut/png.h"
#include "io/bitmap_font.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::TempDir;

namespace {

struct PngFile {
    int width = 0, height = 0, bit_depth = 0, color_type = -1, channels = 0;
    std::vector<std::vector<std::uint8_t>> rows;
    std::map<std::string, std::string> text;

    // Sample c of pixel (x, y), for 8- or 16-bit images.
    int sample(int x, int y, int c) const {
        const auto& r = rows[static_cast<std::size_t>(y)];
        const std::size_t k = static_cast<std::size_t>(x * channels + c);
        if (bit_depth == 16) return r[2 * k] << 8 | r[2 * k + 1];
        return r[k];
    }
};

// Reads a PNG as stored (no transformations). Fails the test on error.
PngFile read_png(const std::string& path) {
    PngFile out;
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (f == nullptr) {
        ADD_FAILURE() << "cannot open " << path;
        return out;
    }
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        std::fclose(f);
        ADD_FAILURE() << "libpng could not read " << path;
        return PngFile{};
    }
    png_init_io(png, f);
    png_read_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
    out.width = static_cast<int>(png_get_image_width(png, info));
    out.height = static_cast<int>(png_get_image_height(png, info));
    out.bit_depth = png_get_bit_depth(png, info);
    out.color_type = png_get_color_type(png, info);
    out.channels = png_get_channels(png, info);
    const std::size_t row_bytes = png_get_rowbytes(png, info);
    png_bytepp rows = png_get_rows(png, info);
    for (int y = 0; y < out.height; ++y) out.rows.emplace_back(rows[y], rows[y] + row_bytes);
    png_textp text = nullptr;
    const int n = png_get_text(png, info, &text, nullptr);
    for (int i = 0; i < n; ++i) out.text[text[i].key] = text[i].text;
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(f);
    return out;
}

std::size_t files_in(const TempDir& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++n;
    return n;
}

using Rgb = std::array<std::uint8_t, 3>;
constexpr Rgb kWhite{255, 255, 255};

bool inside(const PixelRect& r, int x, int y) {
    return x >= r.x && y >= r.y && x < r.x + r.width && y < r.y + r.height;
}

bool overlap(const PixelRect& a, const PixelRect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

// A grid with values[j * nx + i] = f(i, j).
template <class F>
Heatmap grid(int nx, int ny, F f) {
    Heatmap h;
    h.title = "test field";
    h.x = {"cos_theta", Axis{"cos_theta", 0.0, 1.0, nx, Placement::center, Warp::linear}};
    h.y = {"alpha", Axis{"alpha", 0.0, 1.0, ny, Placement::center, Warp::linear}};
    h.colorbar_label = "value";
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) h.values.push_back(f(i, j));
    return h;
}

// The albedo-like sample field of the README: 128 x 128, alpha square-warped.
Heatmap albedo_sample() {
    Heatmap h = grid(128, 128, [](int, int) { return 0.0; });
    h.title = "ggx albedo E(mu, alpha)";
    h.y.axis.warp = Warp::square;
    h.colorbar_label = "E = A + B (directional albedo)";
    for (int j = 0; j < 128; ++j)
        for (int i = 0; i < 128; ++i) {
            const double mu = h.x.axis.value(i), a = h.y.axis.value(j);
            h.values[static_cast<std::size_t>(j * 128 + i)] = 1.0 - a * (0.3 + 0.5 * std::pow(1.0 - mu, 3));
        }
    return h;
}

}  // namespace

// ---------------------------------------------------------------- 16-bit PNG

TEST(Png16, RoundTripsEveryChannelCountExactly) {
    TempDir dir;
    const int w = 7, h = 5;
    const png_byte types[4] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                               PNG_COLOR_TYPE_RGBA};
    for (int c = 1; c <= 4; ++c) {
        std::vector<double> v;
        for (int k = 0; k < w * h * c; ++k) v.push_back(std::fmod(k * 0.618033988749895, 1.0));
        v[0] = 0.0;
        v[1] = 1.0;
        v[2] = 1.0 / 3.0;
        v[3] = 0.75 / 65535.0;  // rounds to the first step
        const std::string path = dir / ("t" + std::to_string(c) + ".png");
        write_png16(path, w, h, c, v, {{"brdflut", "{\"table\": \"x\"}"}});
        const PngFile f = read_png(path);
        ASSERT_EQ(f.width, w);
        ASSERT_EQ(f.height, h);
        EXPECT_EQ(f.bit_depth, 16);
        EXPECT_EQ(f.color_type, types[c - 1]);
        ASSERT_EQ(f.channels, c);
        EXPECT_EQ(f.text.at("brdflut"), "{\"table\": \"x\"}");
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int k = 0; k < c; ++k) {
                    const double value = v[static_cast<std::size_t>((y * w + x) * c + k)];
                    ASSERT_EQ(f.sample(x, y, k), std::lround(value * 65535.0))
                        << "channels " << c << " pixel " << x << "," << y << " channel " << k;
                }
        EXPECT_EQ(f.sample(0, 0, 0), 0);
        EXPECT_EQ(f.sample(3 / c, 0, 3 % c), 1);
    }
    EXPECT_EQ(png16_sample(1.0), 65535);
    EXPECT_EQ(png16_sample(0.5), 32768);  // 32767.5 rounds away from zero
}

TEST(Png16, RefusesValuesOutsideUnitIntervalNamingTheFirstAndWritesNothing) {
    TempDir dir;
    const std::string path = dir / "bad.png";
    std::vector<double> v(4 * 3 * 2, 0.5);
    v[7] = 1.0000001;  // pixel 3 = (x 3, y 0), channel 1
    v[9] = -2.0;
    try {
        write_png16(path, 4, 3, 2, v);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("value 1.0000001 "), std::string::npos) << m;
        EXPECT_NE(m.find("index 7 "), std::string::npos) << m;
        EXPECT_NE(m.find("pixel x 3, y 0, channel 1"), std::string::npos) << m;
        EXPECT_NE(m.find("[0, 1]"), std::string::npos) << m;
    }
    EXPECT_EQ(files_in(dir), 0u);

    v[7] = 0.5;
    v[9] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(write_png16(path, 4, 3, 2, v), Error);
    v[9] = -0.0;  // zero is allowed, whatever its sign
    v[10] = -1e-300;
    try {
        write_png16(path, 4, 3, 2, v);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("index 10 "), std::string::npos) << e.what();
    }
    EXPECT_EQ(files_in(dir), 0u);
}

TEST(Png16, RefusedWriteLeavesThePreviousFileUntouched) {
    TempDir dir;
    const std::string path = dir / "t.png";
    write_png16(path, 2, 2, 1, {0.0, 0.25, 0.5, 1.0});
    const std::string before = test::read_file(path);
    EXPECT_THROW(write_png16(path, 2, 2, 1, {0.0, 0.25, 1.5, 1.0}), Error);
    EXPECT_EQ(test::read_file(path), before);
    EXPECT_EQ(files_in(dir), 1u);
}

TEST(Png16, RefusesBadChannelCountsSizesAndKeywords) {
    TempDir dir;
    const std::string path = dir / "t.png";
    EXPECT_THROW(write_png16(path, 1, 1, 0, {}), Error);
    EXPECT_THROW(write_png16(path, 1, 1, 5, std::vector<double>(5, 0.0)), Error);
    EXPECT_THROW(write_png16(path, 2, 2, 1, std::vector<double>(3, 0.0)), Error);
    EXPECT_THROW(write_png16(path, 0, 2, 1, {}), Error);
    EXPECT_THROW(write_png16(path, 1, 1, 1, {0.0}, {{"", "empty keyword"}}), Error);
    EXPECT_THROW(write_png16(path, 1, 1, 1, {0.0}, {{std::string(80, 'k'), "long keyword"}}), Error);
    try {
        write_png16(path, 1, 1, 7, std::vector<double>(7, 0.0));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("channels 7"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("1 to 4"), std::string::npos) << e.what();
    }
    EXPECT_EQ(files_in(dir), 0u);
}

TEST(Png16, UnwritableFolderIsARuntimeErrorNamingThePath) {
    TempDir dir;
    const std::string path = dir / "missing/t.png";
    try {
        write_png16(path, 1, 1, 1, {0.5});
        FAIL() << "expected an error";
    } catch (const RuntimeError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
}

// ----------------------------------------------------------------- 8-bit RGB

TEST(PngRgb8, RoundTripsBytesExactly) {
    TempDir dir;
    const int w = 5, h = 3;
    std::vector<std::uint8_t> rgb;
    for (int k = 0; k < w * h * 3; ++k) rgb.push_back(static_cast<std::uint8_t>(k * 37 % 256));
    write_png_rgb8(dir / "t.png", w, h, rgb);
    const PngFile f = read_png(dir / "t.png");
    ASSERT_EQ(f.width, w);
    ASSERT_EQ(f.height, h);
    EXPECT_EQ(f.bit_depth, 8);
    EXPECT_EQ(f.color_type, PNG_COLOR_TYPE_RGB);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(f.sample(x, y, c), rgb[static_cast<std::size_t>((y * w + x) * 3 + c)]);
    EXPECT_THROW(write_png_rgb8(dir / "u.png", w, h, std::vector<std::uint8_t>(10)), Error);
}

// ---------------------------------------------------------- colours and font

TEST(Viridis, EndsAndMiddleMatchTheMatplotlibTable) {
    EXPECT_EQ(viridis(0.0), (Rgb{68, 1, 84}));
    EXPECT_EQ(viridis(1.0), (Rgb{253, 231, 37}));
    EXPECT_EQ(viridis(0.5), (Rgb{33, 145, 140}));  // entry 128: (0.127568, 0.566949, 0.550556)
    EXPECT_EQ(viridis(-3.0), viridis(0.0));
    EXPECT_EQ(viridis(7.0), viridis(1.0));
    // Lightness rises along the map (luma, sampled every 16 entries).
    auto luma = [](Rgb c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; };
    for (int k = 0; k + 16 < 256; k += 16)
        EXPECT_LT(luma(viridis(k / 256.0)), luma(viridis((k + 16) / 256.0))) << k;
    std::set<Rgb> distinct;
    for (int k = 0; k < 256; ++k) distinct.insert(viridis((k + 0.5) / 256.0));
    EXPECT_GE(distinct.size(), 250u);
    EXPECT_EQ(distinct.count(kHeatmapNonFiniteColor), 0u);
    EXPECT_EQ(distinct.count(kHeatmapHighlightColor), 0u);
}

TEST(BitmapFont, EveryPrintableGlyphIsWellFormedAndDistinct) {
    std::set<std::string> seen;
    for (int c = 32; c <= 126; ++c) {
        const char* p = font::glyph_pattern(static_cast<char>(c));
        ASSERT_NE(p, nullptr) << c;
        const std::string s = p;
        EXPECT_EQ((s.size() + 1) % 6, 0u) << "'" << static_cast<char>(c) << "': " << s;
        EXPECT_LE((s.size() + 1) / 6, static_cast<std::size_t>(font::kGlyphHeight)) << static_cast<char>(c);
        int ink = 0;
        for (std::size_t k = 0; k < s.size(); ++k) {
            if (k % 6 == 5)
                EXPECT_EQ(s[k], ' ') << static_cast<char>(c);
            else
                EXPECT_TRUE(s[k] == '#' || s[k] == '.') << static_cast<char>(c);
            ink += s[k] == '#';
        }
        EXPECT_EQ(ink == 0, c == ' ') << static_cast<char>(c);
        // Trailing blank rows are implied: compare without them.
        std::string trimmed = s;
        while (trimmed.size() > 5 && trimmed.substr(trimmed.size() - 5) == ".....") trimmed.resize(trimmed.size() - 6);
        EXPECT_TRUE(seen.insert(trimmed).second) << "'" << static_cast<char>(c) << "' repeats another glyph";
    }
    EXPECT_EQ(font::glyph_pattern('\n'), nullptr);
    EXPECT_TRUE(font::glyph_pixel('\x01', 1, 0));  // drawn as '?', whose top row is .###.
    EXPECT_TRUE(font::glyph_pixel('_', 0, 7));     // the underscore sits below the baseline
    EXPECT_FALSE(font::glyph_pixel('A', 0, 8));
}

// ------------------------------------------------------------------ heatmaps

TEST(Heatmap, WrittenPngIsTheRenderedRgbImageWithItsTitle) {
    TempDir dir;
    const Heatmap h = albedo_sample();
    const HeatmapImage img = render_heatmap(h);
    write_heatmap_png(dir / "e.png", h);
    const PngFile f = read_png(dir / "e.png");
    ASSERT_EQ(f.width, img.width);
    ASSERT_EQ(f.height, img.height);
    EXPECT_EQ(f.bit_depth, 8);
    EXPECT_EQ(f.color_type, PNG_COLOR_TYPE_RGB);
    EXPECT_EQ(f.text.at("Title"), "ggx albedo E(mu, alpha)");
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
            const Rgb p = img.pixel(x, y);
            for (int c = 0; c < 3; ++c) ASSERT_EQ(f.sample(x, y, c), p[static_cast<std::size_t>(c)]) << x << "," << y;
        }
    // 128 cells of 4 pixels on each axis.
    EXPECT_EQ(img.plot.width, 512);
    EXPECT_EQ(img.plot.height, 512);
    EXPECT_EQ(files_in(dir), 1u);
}

TEST(Heatmap, LargestCellIsLastViridisColourSmallestFirstWithYUp) {
    // values grow with i and j: the smallest cell is bottom-left, the largest top-right.
    const Heatmap h = grid(6, 4, [](int i, int j) { return 0.25 + i + 10.0 * j; });
    const HeatmapImage img = render_heatmap(h);
    EXPECT_EQ(img.vmin, 0.25);
    EXPECT_EQ(img.vmax, 35.25);
    const PixelRect& p = img.plot;
    EXPECT_EQ(img.pixel(p.x + 1, p.y + p.height - 2), viridis(0.0));  // bottom-left
    EXPECT_EQ(img.pixel(p.x + p.width - 2, p.y + 1), viridis(1.0));   // top-right
    const auto top = img.cell_center(5, 3), bottom = img.cell_center(0, 0);
    EXPECT_EQ(img.pixel(top[0], top[1]), viridis(1.0));
    EXPECT_EQ(img.pixel(bottom[0], bottom[1]), viridis(0.0));
    EXPECT_LT(top[1], bottom[1]);
    // Cell (2, 1) = 12.25 maps to entry floor(256 * 12 / 35) = 87.
    const auto c = img.cell_center(2, 1);
    EXPECT_EQ(img.pixel(c[0], c[1]), viridis((87 + 0.5) / 256.0));
    // Colour bar: vmax colour at the top, vmin colour at the bottom.
    EXPECT_EQ(img.pixel(img.colorbar.x + 5, img.colorbar.y), viridis(1.0));
    EXPECT_EQ(img.pixel(img.colorbar.x + 5, img.colorbar.y + img.colorbar.height - 1), viridis(0.0));
}

TEST(Heatmap, ExplicitColourRangeClampsValuesOutsideIt) {
    Heatmap h = grid(3, 1, [](int i, int) { return i == 0 ? -5.0 : (i == 1 ? 0.5 : 9.0); });
    h.vmin = 0.0;
    h.vmax = 1.0;
    const HeatmapImage img = render_heatmap(h);
    auto at = [&](int i) {
        const auto c = img.cell_center(i, 0);
        return img.pixel(c[0], c[1]);
    };
    EXPECT_EQ(at(0), viridis(0.0));
    EXPECT_EQ(at(1), viridis(0.5));
    EXPECT_EQ(at(2), viridis(1.0));
}

TEST(Heatmap, NonFiniteCellsAreGreyAndTheLegendShowsTheGrey) {
    auto count_outside_plot = [](const HeatmapImage& img, Rgb colour) {
        int n = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x)
                if (!inside(img.plot, x, y) && img.pixel(x, y) == colour) ++n;
        return n;
    };
    Heatmap h = grid(5, 4, [](int i, int j) { return i + j * 0.5; });
    const int plain_text_boxes = static_cast<int>(render_heatmap(h).text.size());
    EXPECT_EQ(count_outside_plot(render_heatmap(h), kHeatmapNonFiniteColor), 0);

    h.values[1 * 5 + 2] = std::numeric_limits<double>::quiet_NaN();
    h.values[3 * 5 + 4] = std::numeric_limits<double>::infinity();  // the largest cell
    const HeatmapImage img = render_heatmap(h);
    const auto nan = img.cell_center(2, 1), inf = img.cell_center(4, 3);
    EXPECT_EQ(img.pixel(nan[0], nan[1]), kHeatmapNonFiniteColor);
    EXPECT_EQ(img.pixel(inf[0], inf[1]), kHeatmapNonFiniteColor);
    // The colour range ignores them: the largest finite cell (4, 2) = 5 is the top colour.
    EXPECT_EQ(img.vmax, 5.0);
    const auto top = img.cell_center(4, 2);
    EXPECT_EQ(img.pixel(top[0], top[1]), viridis(1.0));
    // A grey swatch and one more line of text in the legend.
    EXPECT_GE(count_outside_plot(img, kHeatmapNonFiniteColor), 100);
    EXPECT_EQ(static_cast<int>(img.text.size()), plain_text_boxes + 1);
}

TEST(Heatmap, HighlightOutlinesFiniteCellsAboveTheThresholdOnTheirBorders) {
    // 4 x 4 cells of 128 pixels; cell (1, 2) = 2 > 1, cell (3, 0) infinite.
    Heatmap h = grid(4, 4, [](int i, int j) { return i == 1 && j == 2 ? 2.0 : 0.5 + 0.01 * (i + j); });
    h.values[3] = std::numeric_limits<double>::infinity();
    h.highlight = HeatmapHighlight{1.0, ""};
    const HeatmapImage img = render_heatmap(h);
    ASSERT_EQ(img.plot.width, 512);
    const auto c = img.cell_center(1, 2);  // (x 192, y 191) in the plot, cell spans x 128..255, y 128..255
    EXPECT_EQ(img.pixel(c[0], c[1]), viridis(1.0));
    const int left = img.plot.x + 128, top = img.plot.y + 128;
    for (int d = 0; d < 2; ++d) {
        EXPECT_EQ(img.pixel(left + d, c[1]), kHeatmapHighlightColor) << d;        // left border, inside
        EXPECT_EQ(img.pixel(left + 127 - d, c[1]), kHeatmapHighlightColor) << d;  // right border
        EXPECT_EQ(img.pixel(c[0], top + d), kHeatmapHighlightColor) << d;         // top border
        EXPECT_EQ(img.pixel(c[0], top + 127 - d), kHeatmapHighlightColor) << d;   // bottom border
    }
    EXPECT_NE(img.pixel(left + 2, c[1]), kHeatmapHighlightColor);
    EXPECT_NE(img.pixel(left - 1, c[1]), kHeatmapHighlightColor);  // the neighbour cell is not drawn on
    // The infinite cell is grey, not outlined.
    const PixelRect& p = img.plot;
    EXPECT_EQ(img.pixel(p.x + 384, p.y + p.height - 64), kHeatmapNonFiniteColor);
    EXPECT_EQ(img.pixel(p.x + 384, p.y + p.height - 1), kHeatmapNonFiniteColor);
    int magenta = 0;
    for (int y = p.y; y < p.y + p.height; ++y)
        for (int x = p.x; x < p.x + p.width; ++x) magenta += img.pixel(x, y) == kHeatmapHighlightColor;
    EXPECT_EQ(magenta, 4 * 2 * 128 - 4 * 4);  // one ring 2 pixels wide around one 128-pixel cell
}

TEST(Heatmap, TicksSitAtRoundValuesThroughTheAxisWarp) {
    // alpha with the square warp: the tick at alpha = 0.2 sits at sqrt(0.2) of the height.
    const HeatmapImage img = render_heatmap(albedo_sample());
    const PixelRect& p = img.plot;
    auto tick_at_row = [&](int row) {
        const Rgb ink{0, 0, 0};
        return img.pixel(p.x - 4, p.y + row) == ink || img.pixel(p.x - 4, p.y + row - 1) == ink;
    };
    for (const double alpha : {0.2, 0.4, 0.6, 0.8}) {
        const int row = p.height - static_cast<int>(std::lround(std::sqrt(alpha) * p.height));
        EXPECT_TRUE(tick_at_row(row)) << alpha;
        const int linear_row = p.height - static_cast<int>(std::lround(alpha * p.height));
        EXPECT_FALSE(tick_at_row(linear_row)) << alpha;
    }
    // x is linear: ticks every 0.2 of the width.
    for (int k = 0; k <= 5; ++k) EXPECT_EQ(img.pixel(p.x + k * p.width / 5 - (k == 5), p.y + p.height + 3), (Rgb{0, 0, 0})) << k;
}

TEST(Heatmap, TextIsInkedInsideTheImageAndOverlapsNothing) {
    std::vector<Heatmap> cases;
    cases.push_back(albedo_sample());
    {
        Heatmap h = grid(8, 6, [](int i, int j) { return 0.8 + 0.05 * i + 0.03 * j; });
        h.y = {"sigma [rad]", Axis{"sigma", 1e-3, 2.0, 6, Placement::endpoints, Warp::log}};
        h.x.axis.placement = Placement::endpoints;
        h.values[3] = std::numeric_limits<double>::quiet_NaN();
        h.highlight = HeatmapHighlight{1.0, "E > 1: gains energy"};
        cases.push_back(h);
    }
    {
        Heatmap h = grid(1000, 3, [](int i, int j) { return 1e-8 * (1 + std::sin(i * 0.01 + j)); });
        h.title = "a long title that is wider than the plot and its colour bar put together, by far";
        h.colorbar_label = "a colour bar label much longer than the five hundred pixels of the plot's side";
        cases.push_back(h);
    }
    cases.push_back(grid(1, 1, [](int, int) { return 3.0; }));
    {
        // Crowded ticks: eleven decades on x, a sqrt warp bunching ticks at the bottom of y.
        Heatmap h = grid(40, 30, [](int i, int j) { return i * j; });
        h.x = {"radius", Axis{"radius", 1e-6, 1e4, 40, Placement::center, Warp::log}};
        h.y = {"y", Axis{"y", 0.25, 0.3, 30, Placement::center, Warp::sqrt}};
        cases.push_back(h);
    }
    {
        // Rotated labels longer than the plot, a long legend line, and an
        // x range too narrow beside its magnitude for any tick.
        Heatmap h = grid(300, 20, [](int i, int j) { return i - j; });
        h.x.axis.min = 1000.0;
        h.x.axis.max = 1000.0 + 1e-12;
        h.y.label = std::string(60, 'y') + " a y label longer than the side of the plot";
        h.colorbar_label = std::string(60, 'c') + " a colour bar label longer than the plot";
        h.highlight = HeatmapHighlight{5.0, "outline: a legend line that runs well past the colour bar of this plot"};
        h.values[7] = std::numeric_limits<double>::quiet_NaN();
        cases.push_back(h);
    }
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const HeatmapImage img = render_heatmap(cases[k]);
        ASSERT_EQ(img.rgb.size(), static_cast<std::size_t>(img.width) * img.height * 3);
        ASSERT_GE(img.text.size(), 5u) << k;  // title, two labels, ticks, legend
        for (std::size_t a = 0; a < img.text.size(); ++a) {
            const PixelRect& t = img.text[a];
            EXPECT_TRUE(t.x >= 0 && t.y >= 0 && t.x + t.width <= img.width && t.y + t.height <= img.height)
                << "case " << k << " text " << a;
            EXPECT_FALSE(overlap(t, img.plot)) << "case " << k << " text " << a;
            EXPECT_FALSE(overlap(t, img.colorbar)) << "case " << k << " text " << a;
            for (std::size_t b = a + 1; b < img.text.size(); ++b)
                EXPECT_FALSE(overlap(t, img.text[b])) << "case " << k << " texts " << a << ", " << b;
            int ink = 0;
            for (int y = t.y; y < t.y + t.height; ++y)
                for (int x = t.x; x < t.x + t.width; ++x) ink += img.pixel(x, y) == Rgb{0, 0, 0};
            EXPECT_GT(ink, 10) << "case " << k << " text " << a << " is blank";
        }
        // The title is above the plot, and the top text line is not blank.
        EXPECT_LT(img.text.back().y + img.text.back().height, img.plot.y) << k;
        // The frame around the plot and a white margin around everything.
        EXPECT_EQ(img.pixel(img.plot.x - 1, img.plot.y + 3), (Rgb{0, 0, 0})) << k;
        for (int x = 0; x < img.width; ++x) EXPECT_EQ(img.pixel(x, 0), kWhite) << k;
    }
}

TEST(Heatmap, RefusesInconsistentOrEmptyInput) {
    Heatmap h = grid(3, 2, [](int i, int j) { return i + j; });
    h.values.pop_back();
    try {
        render_heatmap(h);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("5 values given for 3 x 2 cells"), std::string::npos) << e.what();
    }
    h = grid(3, 2, [](int i, int j) { return i + j; });
    h.vmin = 2.0;
    h.vmax = 2.0;
    EXPECT_THROW(render_heatmap(h), Error);
    h.vmax = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(render_heatmap(h), Error);
    h = grid(3, 2, [](int i, int j) { return i + j; });
    h.x.axis.count = 0;
    h.values.clear();
    EXPECT_THROW(render_heatmap(h), Error);
    h = grid(3, 2, [](int i, int j) { return i + j; });
    h.highlight = HeatmapHighlight{std::numeric_limits<double>::infinity(), ""};
    EXPECT_THROW(render_heatmap(h), Error);
    TempDir dir;
    EXPECT_THROW(write_heatmap_png(dir / "h.png", h), Error);
    EXPECT_EQ(files_in(dir), 0u);
}
