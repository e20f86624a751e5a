#include "brdflut/lut.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <cstring>

#include "brdflut/error.h"
#include "brdflut/generate.h"

namespace brdflut {
namespace {
constexpr const char* kLetters = "RGBA";

int letter_index(char c) {
    const char* p = std::strchr(kLetters, c);
    return (p && c) ? static_cast<int>(p - kLetters) : -1;
}

// Position in the image (pixel offset) of a texel given per axis indices.
std::size_t pixel_of(const LutDescription& d, const std::vector<int>& idx) {
    const auto& axes = d.settings.axes;
    std::vector<int> pos(idx);
    for (std::size_t a = 0; a < axes.size(); ++a)
        if (a < d.flip.size() && d.flip[a]) pos[a] = axes[a].count - 1 - idx[a];
    std::size_t p = 0, stride = 1;
    for (std::size_t a = 0; a < axes.size(); ++a) {
        p += static_cast<std::size_t>(pos[a]) * stride;
        stride *= static_cast<std::size_t>(axes[a].count);
    }
    return p;
}
}  // namespace

LutDescription describe_from_metadata(const ExrImage& img, const std::string& path) {
    if (!img.has_metadata)
        throw RuntimeError("'" + path + "' has no brdflut metadata; describe it with --as <table id> "
                           "and the axis options");
    LutDescription d;
    try {
        const auto& m = img.metadata;
        const std::string id = m.at("table").get<std::string>();
        try {
            d.def = &find_table(id);
        } catch (const Error& e) {
            throw RuntimeError("'" + path + "': " + e.what());
        }
        d.settings = default_settings(*d.def);
        d.settings.axes = axes_from_json(m.at("axes"));
        if (m.contains("options"))
            for (const auto& [k, v] : m.at("options").items()) d.settings.params[k] = v.get<std::string>();
        validate_settings(*d.def, d.settings);
    } catch (const nlohmann::json::exception& e) {
        throw RuntimeError("'" + path + "': metadata is malformed: " + e.what());
    } catch (const Error& e) {
        throw RuntimeError("'" + path + "': metadata does not describe a valid table: " + e.what());
    }
    for (int c = 0; c < static_cast<int>(d.def->channels.size()); ++c) d.channel_map.push_back({c});
    d.flip.assign(d.settings.axes.size(), false);
    return d;
}

std::vector<std::vector<int>> parse_channel_map(const std::string& spec, int table_channels) {
    std::vector<std::vector<int>> map;
    std::stringstream ss(spec);
    std::string item;
    const std::string allowed = std::string(kLetters).substr(0, static_cast<std::size_t>(table_channels));
    while (std::getline(ss, item, ',')) {
        const std::size_t eq = item.find('=');
        auto bad = [&](const std::string& why) {
            return Error("--channels item '" + item + "' " + why + "; expected FILE=TABLE[+TABLE], e.g. R=G,G=R+G, "
                         "with table channels from " + allowed);
        };
        if (eq != 1 || letter_index(item[0]) < 0) throw bad("must start with a file channel R, G, B or A");
        const std::size_t file_c = static_cast<std::size_t>(letter_index(item[0]));
        if (file_c != map.size()) throw bad("is out of order: list the file channels from R");
        std::vector<int> sum;
        for (std::size_t i = 2; i < item.size(); ++i) {
            if (item[i] == '+') continue;
            const int t = letter_index(item[i]);
            if (t < 0 || t >= table_channels) throw bad("names a table channel that does not exist");
            sum.push_back(t);
        }
        if (sum.empty()) throw bad("names no table channel");
        map.push_back(sum);
    }
    if (map.empty()) throw Error("--channels '" + spec + "' is empty");
    return map;
}

void check_fits(const ExrImage& img, const LutDescription& d, const std::string& path) {
    const auto& axes = d.settings.axes;
    const int w = axes[0].count;
    int h = axes.size() > 1 ? axes[1].count : 1;
    if (axes.size() > 2) h *= axes[2].count;
    if (img.width != w || img.height != h)
        throw RuntimeError("'" + path + "' is " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                           " but the table described is " + std::to_string(w) + "x" + std::to_string(h));
    if (d.channel_map.size() > img.channel_names.size())
        throw RuntimeError("'" + path + "' has " + std::to_string(img.channel_names.size()) +
                           " channel(s) but the description needs " + std::to_string(d.channel_map.size()));
}

CompareReport compare_lut(const ExrImage& img, const LutDescription& d, int threads, std::size_t worst_count) {
    GenerateOptions opt;
    opt.threads = threads;
    const Table exact = generate(*d.def, d.settings, opt);
    CompareReport rep;
    rep.exact_error_bound = error_bound(exact, PixelType::float32);
    const std::size_t nfile = img.channel_names.size();
    const std::size_t texels = exact.texel_count();
    rep.max_error_map.assign(texels, 0.0);
    std::vector<double> sum_sq(d.channel_map.size(), 0.0);
    rep.channels.resize(d.channel_map.size());
    for (std::size_t c = 0; c < d.channel_map.size(); ++c) rep.channels[c].channel = img.channel_names[c];
    std::vector<TexelError> all;
    for (std::size_t k = 0; k < texels; ++k) {
        std::vector<int> idx;
        std::vector<double> params;
        std::size_t rest = k;
        for (const Axis& a : d.settings.axes) {
            const int i = static_cast<int>(rest % static_cast<std::size_t>(a.count));
            rest /= static_cast<std::size_t>(a.count);
            idx.push_back(i);
            params.push_back(a.value(i));
        }
        const std::size_t p = pixel_of(d, idx);
        for (std::size_t c = 0; c < d.channel_map.size(); ++c) {
            double want = 0.0;
            for (int t : d.channel_map[c]) want += exact.at(k, t);
            const double stored = img.pixels[p * nfile + c];
            const double err = stored - want;
            const double a = std::isfinite(err) ? std::abs(err) : HUGE_VAL;
            ChannelError& ce = rep.channels[c];
            ce.max_abs = std::max(ce.max_abs, a);
            sum_sq[c] += std::isfinite(err) ? err * err : HUGE_VAL;
            rep.max_error_map[k] = std::max(rep.max_error_map[k], a);
            all.push_back({k, params, img.channel_names[c], stored, want, err});
        }
    }
    for (std::size_t c = 0; c < rep.channels.size(); ++c)
        rep.channels[c].rms = std::sqrt(sum_sq[c] / static_cast<double>(texels));
    const std::size_t n = std::min(worst_count, all.size());
    std::partial_sort(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(n), all.end(),
                      [](const TexelError& a, const TexelError& b) {
                          const double ea = std::isfinite(a.error) ? std::abs(a.error) : HUGE_VAL;
                          const double eb = std::isfinite(b.error) ? std::abs(b.error) : HUGE_VAL;
                          if (ea != eb) return ea > eb;
                          return a.texel < b.texel;
                      });
    all.resize(n);
    rep.worst = std::move(all);
    return rep;
}

std::vector<ChannelStats> channel_stats(const ExrImage& img) {
    std::vector<ChannelStats> out;
    const std::size_t nc = img.channel_names.size();
    const std::size_t n = static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height);
    for (std::size_t c = 0; c < nc; ++c) {
        ChannelStats s;
        s.channel = img.channel_names[c];
        s.min = HUGE_VAL;
        s.max = -HUGE_VAL;
        double sum = 0.0;
        long long finite = 0;
        for (std::size_t p = 0; p < n; ++p) {
            const double v = img.pixels[p * nc + c];
            if (!std::isfinite(v)) {
                ++s.non_finite;
                continue;
            }
            s.min = std::min(s.min, v);
            s.max = std::max(s.max, v);
            sum += v;
            ++finite;
        }
        s.mean = finite ? sum / static_cast<double>(finite) : std::nan("");
        if (!finite) s.min = s.max = std::nan("");
        out.push_back(s);
    }
    return out;
}

double sample_lut(const ExrImage& img, const LutDescription& d, const std::vector<double>& params,
                  int file_channel) {
    const auto& axes = d.settings.axes;
    if (axes.size() > 2) throw Error("sampling 3-D tables is not supported");
    if (params.size() != axes.size())
        throw Error("expected " + std::to_string(axes.size()) + " parameter(s), got " + std::to_string(params.size()));
    const std::size_t nc = img.channel_names.size();
    // Continuous texel coordinate along each axis: texel i's centre is at i.
    std::vector<double> pos;
    for (std::size_t a = 0; a < axes.size(); ++a) {
        const Axis& ax = axes[a];
        const double u = ax.u_of_value(params[a]);
        double p = ax.placement == Placement::center ? u * ax.count - 0.5 : u * (ax.count - 1);
        if (a < d.flip.size() && d.flip[a]) p = ax.count - 1 - p;
        pos.push_back(std::clamp(std::isfinite(p) ? p : 0.0, 0.0, static_cast<double>(ax.count - 1)));
    }
    auto at = [&](int x, int y) {
        return img.pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x)) * nc +
                          static_cast<std::size_t>(file_channel)];
    };
    const int x0 = static_cast<int>(std::floor(pos[0]));
    const int x1 = std::min(x0 + 1, axes[0].count - 1);
    const double fx = pos[0] - x0;
    if (axes.size() == 1) return (1 - fx) * at(x0, 0) + fx * at(x1, 0);
    const int y0 = static_cast<int>(std::floor(pos[1]));
    const int y1 = std::min(y0 + 1, axes[1].count - 1);
    const double fy = pos[1] - y0;
    return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) + fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1));
}

}  // namespace brdflut
