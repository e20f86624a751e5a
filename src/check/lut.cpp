#include "brdflut/lut.h"

#include <algorithm>
#include <cmath>

#include "brdflut/error.h"
#include "brdflut/generate.h"

namespace brdflut {

std::string_view to_string(ValueTransform t) { return t == ValueTransform::srgb ? "srgb" : "none"; }

ValueTransform value_transform_from_string(std::string_view s) {
    if (s == "none") return ValueTransform::none;
    if (s == "srgb") return ValueTransform::srgb;
    throw Error("--transform '" + std::string(s) + "' is not known; allowed: none, srgb");
}

void apply_value_transform(Table& t, ValueTransform transform) {
    if (transform == ValueTransform::none) return;
    const std::size_t nc = t.channels.size();
    for (std::size_t k = 0; k < t.values.size(); ++k) {
        if (k % nc == 3) continue;  // alpha is linear
        const double v = t.values[k];
        const double e = t.errors[k];
        const double out = srgb_eotf(v);
        // The slope of the EOTF over [v - e, v + e] bounds the new error.
        const double slope = std::max(std::abs(srgb_eotf(v + e) - out), std::abs(out - srgb_eotf(v - e)));
        t.values[k] = out;
        t.errors[k] = slope;
    }
}

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
        if (m.contains("channel_map"))
            d.settings.channel_map = parse_channel_map(m.at("channel_map").get<std::string>(),
                                                       static_cast<int>(d.def->channels.size()));
        validate_settings(*d.def, d.settings);
    } catch (const nlohmann::json::exception& e) {
        throw RuntimeError("'" + path + "': metadata is malformed: " + e.what());
    } catch (const Error& e) {
        throw RuntimeError("'" + path + "': metadata does not describe a valid table: " + e.what());
    }
    return d;
}

namespace {
// Largest |error| first (non-finite errors as the largest), then by texel.
bool by_error(const TexelError& x, const TexelError& y) {
    const double ex = std::isfinite(x.error) ? std::abs(x.error) : HUGE_VAL;
    const double ey = std::isfinite(y.error) ? std::abs(y.error) : HUGE_VAL;
    if (ex != ey) return ex > ey;
    return x.texel < y.texel;
}

int stored_channel_count(const LutDescription& d) {
    return static_cast<int>(d.settings.channel_map.empty() ? d.def->channels.size() : d.settings.channel_map.size());
}
}  // namespace

void check_fits(const ExrImage& img, const LutDescription& d, const std::string& path) {
    const auto& axes = d.settings.axes;
    const int w = axes[0].count;
    long long h = axes.size() > 1 ? axes[1].count : 1;
    if (axes.size() > 2) h *= axes[2].count;
    if (img.width != w || img.height != h)
        throw RuntimeError("'" + path + "' is " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                           " but the table described is " + std::to_string(w) + "x" + std::to_string(h));
    const std::size_t need = static_cast<std::size_t>(stored_channel_count(d));
    if (need > img.channel_names.size())
        throw RuntimeError("'" + path + "' has " + std::to_string(img.channel_names.size()) +
                           " channel(s) but the description needs " + std::to_string(need));
}

bool is_flat(const ExrImage& img) { return img.height == 1 && img.depth == 1; }

void reshape_flat(ExrImage& img, const std::vector<Axis>& axes, int table_channels, const std::string& path) {
    const long long numbers = static_cast<long long>(img.pixels.size());
    long long texels = 1;
    std::string shape;
    for (const Axis& a : axes) {
        texels *= a.count;
        if (!shape.empty()) shape += 'x';
        shape += std::to_string(a.count);
    }
    const long long file_channels = static_cast<long long>(img.channel_names.size());
    long long channels = file_channels;
    if (numbers != texels * channels) {
        if (file_channels == 1 && numbers == texels * table_channels) channels = table_channels;
        else
            throw RuntimeError("'" + path + "' is a flat array of " + std::to_string(numbers) +
                               " numbers; the table's layout is " + shape + " texels of " +
                               std::to_string(table_channels) + " channel(s), which needs " +
                               std::to_string(texels) + " (one channel) or " +
                               std::to_string(texels * table_channels) +
                               "; give the file's shape with --shape or the layout's counts with --size");
    }
    static const char* kNames[4] = {"R", "G", "B", "A"};
    img.width = axes[0].count;
    img.depth = axes.size() > 2 ? axes[2].count : 1;
    img.height = static_cast<int>(texels / axes[0].count);
    img.channel_names.assign(kNames, kNames + channels);
}

Tolerance parse_tolerance(const std::string& s) {
    Tolerance t;
    const bool relative = !s.empty() && s.back() == '%';
    const std::string number = relative ? s.substr(0, s.size() - 1) : s;
    std::size_t used = 0;
    double v = -1;
    try {
        v = std::stod(number, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (number.empty() || used != number.size() || !std::isfinite(v) || v < 0)
        throw Error("--tolerance '" + s + "' is not valid; allowed: a number >= 0 (absolute, e.g. 1e-4) or a "
                    "percentage of the exact value (e.g. 0.1%)");
    if (relative) t.rel = v / 100.0;
    else t.abs = v;
    t.source = "--tolerance " + s;
    return t;
}

double storage_step(const ExrImage& img, double v) {
    if (is_integer(img.storage)) {
        const std::uint32_t q[4] = {0, 0, 0, 0};
        return encoding_step(img.storage, q, 0);
    }
    if (img.printed_step > 0) return img.printed_step;
    const double a = std::abs(v);
    // The spacing of the float type around v (the smallest normal's below it).
    const int mantissa = img.pixel == PixelType::half ? 10 : 23;
    const int min_exp = img.pixel == PixelType::half ? -14 : -126;
    const int e = a > 0 ? std::max(std::ilogb(a), min_exp) : min_exp;
    return std::ldexp(1.0, e - mantissa);
}

double storage_step(const ExrImage& img, std::size_t index, double v) {
    return index < img.steps.size() ? img.steps[index] : storage_step(img, v);
}

Tolerance default_tolerance(const ExrImage& img) {
    Tolerance t;
    if (!is_integer(img.storage) && img.has_metadata && img.metadata.is_object() && img.metadata.contains("error_bound") &&
        img.metadata["error_bound"].is_number()) {
        t.abs = img.metadata["error_bound"].get<double>();
        t.source = "the file's error_bound";
        return t;
    }
    t.steps = 1.0;
    t.source = img.printed_step > 0
                   ? "one unit of the last printed digit of the file's numbers"
                   : "one storage step of the file's " +
                         std::string(img.stored_as()) +
                         " values";
    return t;
}

CompareReport compare_values(const ExrImage& img, const Table& exact, std::size_t worst_count,
                             const Tolerance& tolerance) {
    CompareReport rep;
    rep.tolerance = tolerance;
    rep.exact_error_bound = error_bound(exact, PixelType::float32);
    const std::size_t nfile = img.channel_names.size();
    const std::size_t nc = exact.channels.size();
    const std::size_t texels = exact.texel_count();
    rep.max_error_map.assign(texels, 0.0);
    std::vector<double> sum_sq(nc, 0.0);
    rep.channels.resize(nc);
    for (std::size_t c = 0; c < nc; ++c) rep.channels[c].channel = img.channel_names[c];
    std::vector<TexelError> all, failures;
    auto texel_error = [&](std::size_t k, std::size_t c, double stored, double want, double err) {
        TexelError te{k, {}, img.channel_names[c], stored, want, err};
        std::size_t rest = k;
        for (const Axis& a : exact.axes) {
            const int i = static_cast<int>(rest % static_cast<std::size_t>(a.count));
            rest /= static_cast<std::size_t>(a.count);
            te.params.push_back(a.value(i));
        }
        return te;
    };
    for (std::size_t k = 0; k < texels; ++k) {
        for (std::size_t c = 0; c < nc; ++c) {
            const double want = exact.values[k * nc + c];
            const double stored = img.pixels[k * nfile + c];
            const double err = stored - want;
            const double a = std::isfinite(err) ? std::abs(err) : HUGE_VAL;
            ChannelError& ce = rep.channels[c];
            ce.max_abs = std::max(ce.max_abs, a);
            if (want != 0.0 && storage_step(img, k * nfile + c, want) <= 1e-3 * std::abs(want) &&
                (a / std::abs(want) > ce.max_rel || (ce.max_rel_params.empty() && a == 0.0))) {
                ce.max_rel = a / std::abs(want);
                ce.max_rel_params = texel_error(k, c, stored, want, err).params;
            }
            sum_sq[c] += std::isfinite(err) ? err * err : HUGE_VAL;
            rep.max_error_map[k] = std::max(rep.max_error_map[k], a);
            const double allowed = tolerance.abs + tolerance.rel * std::abs(want) +
                                   tolerance.steps * storage_step(img, k * nfile + c, want) + exact.errors[k * nc + c];
            const bool fails = !(a <= allowed);
            if (fails) ++rep.failed_values;
            // Keep only what can still be among the worst (bounded memory).
            if (worst_count > 0) {
                all.push_back(texel_error(k, c, stored, want, err));
                if (fails) failures.push_back(all.back());
            }
        }
        if (all.size() > 4 * worst_count + 64) {
            for (auto* v : {&all, &failures}) {
                if (v->size() <= worst_count) continue;
                std::nth_element(v->begin(), v->begin() + static_cast<std::ptrdiff_t>(worst_count), v->end(), by_error);
                v->resize(worst_count);
            }
        }
    }
    for (std::size_t c = 0; c < nc; ++c) rep.channels[c].rms = std::sqrt(sum_sq[c] / static_cast<double>(texels));
    for (auto* v : {&all, &failures}) {
        const std::size_t n = std::min(worst_count, v->size());
        std::partial_sort(v->begin(), v->begin() + static_cast<std::ptrdiff_t>(n), v->end(), by_error);
        v->resize(n);
    }
    rep.worst = std::move(all);
    rep.first_failures = std::move(failures);
    return rep;
}

CompareReport compare_lut(const ExrImage& img, const LutDescription& d, int threads, std::size_t worst_count,
                          const Tolerance& tolerance) {
    GenerateOptions opt;
    opt.threads = threads;
    Table exact = generate(*d.def, d.settings, opt);
    apply_value_transform(exact, d.values);
    return compare_values(img, exact, worst_count, tolerance);
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
    if (params.size() != axes.size())
        throw Error("expected " + std::to_string(axes.size()) + " parameter(s), got " + std::to_string(params.size()));
    const std::size_t nc = img.channel_names.size();
    // Per axis: the two texels around the point and the weight of the second
    // (clamp to edge: both are the edge texel outside the grid).
    int lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    double f[3] = {0.0, 0.0, 0.0};
    for (std::size_t a = 0; a < axes.size(); ++a) {
        const Axis& ax = axes[a];
        const double p = ax.position_of_value(params[a]);
        const double c = std::clamp(std::isfinite(p) ? p : 0.0, 0.0, static_cast<double>(ax.count - 1));
        lo[a] = static_cast<int>(std::floor(c));
        hi[a] = std::min(lo[a] + 1, ax.count - 1);
        f[a] = c - lo[a];
    }
    const std::size_t w = static_cast<std::size_t>(axes[0].count);
    const std::size_t h = axes.size() > 1 ? static_cast<std::size_t>(axes[1].count) : 1;
    auto at = [&](int x, int y, int z) {
        const std::size_t pixel = (static_cast<std::size_t>(z) * h + static_cast<std::size_t>(y)) * w +
                                  static_cast<std::size_t>(x);
        return img.pixels[pixel * nc + static_cast<std::size_t>(file_channel)];
    };
    double sum = 0.0;
    for (int corner = 0; corner < (1 << axes.size()); ++corner) {
        int idx[3] = {0, 0, 0};
        double weight = 1.0;
        for (std::size_t a = 0; a < axes.size(); ++a) {
            const bool upper = (corner >> a) & 1;
            idx[a] = upper ? hi[a] : lo[a];
            weight *= upper ? f[a] : 1.0 - f[a];
        }
        if (weight != 0.0) sum += weight * at(idx[0], idx[1], idx[2]);
    }
    return sum;
}

}  // namespace brdflut
