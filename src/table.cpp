#include "brdflut/table.h"

#include <Imath/half.h>

#include <cmath>

#include "brdflut/error.h"
#include "brdflut/version.h"

namespace brdflut {

std::string_view to_string(Method m) { return m == Method::quadrature ? "quadrature" : "mc"; }

Method method_from_string(std::string_view s) {
    if (s == "quadrature") return Method::quadrature;
    if (s == "mc") return Method::monte_carlo;
    throw Error("method '" + std::string(s) + "' is not known; allowed: quadrature, mc");
}

std::string_view to_string(Quality q) {
    switch (q) {
        case Quality::draft: return "draft";
        case Quality::standard: return "default";
        case Quality::reference: return "reference";
    }
    return "default";
}

Quality quality_from_string(std::string_view s) {
    if (s == "draft") return Quality::draft;
    if (s == "default") return Quality::standard;
    if (s == "reference") return Quality::reference;
    throw Error("--quality '" + std::string(s) + "' is not known; allowed: draft, default, reference");
}

std::string_view to_string(PixelType p) { return p == PixelType::half ? "half" : "float"; }

PixelType pixel_type_from_string(std::string_view s) {
    if (s == "half") return PixelType::half;
    if (s == "float") return PixelType::float32;
    throw Error("pixel type '" + std::string(s) + "' is not known; allowed: half, float");
}

Storage storage_of(PixelType p) { return p == PixelType::half ? Storage::half : Storage::float32; }

std::string_view to_string(Storage s) {
    switch (s) {
        case Storage::half: return "half";
        case Storage::float32: return "float";
        case Storage::unorm16: return "unorm16";
    }
    return "float";
}

double round_to_storage(double v, Storage s) {
    switch (s) {
        case Storage::half:
            return static_cast<double>(static_cast<float>(Imath::half(static_cast<float>(v))));
        case Storage::float32: return static_cast<double>(static_cast<float>(v));
        case Storage::unorm16: return std::round(v * 65535.0) / 65535.0;  // as png16_sample
    }
    return v;
}

double round_to_storage(double v, PixelType p) { return round_to_storage(v, storage_of(p)); }

int Table::height() const {
    int h = axes.size() > 1 ? axes[1].count : 1;
    if (axes.size() > 2) h *= axes[2].count;
    return h;
}

std::size_t Table::texel_count() const {
    std::size_t n = 1;
    for (const Axis& a : axes) n *= static_cast<std::size_t>(a.count);
    return n;
}

double error_bound(const Table& t, PixelType p) { return error_bound(t, storage_of(p)); }

double error_bound(const Table& t, Storage s) {
    double bound = 0.0;
    for (std::size_t i = 0; i < t.values.size(); ++i) {
        const double v = t.values[i];
        const double rounding = std::abs(round_to_storage(v, s) - v);
        const double e = (i < t.errors.size() ? t.errors[i] : 0.0) + rounding;
        bound = std::max(bound, e);
    }
    return bound;
}

nlohmann::json metadata_json(const Table& t, PixelType p) { return metadata_json(t, storage_of(p)); }

nlohmann::json metadata_json(const Table& t, Storage s) {
    nlohmann::json j;
    j["table"] = t.id;
    j["generator"] = {{"name", kName}, {"version", kVersion}};
    j["model"] = t.model;
    j["options"] = t.options;
    nlohmann::json axes = nlohmann::json::array();
    for (const Axis& a : t.axes) {
        axes.push_back({{"name", a.name},
                        {"min", a.min},
                        {"max", a.max},
                        {"count", a.count},
                        {"placement", to_string(a.placement)},
                        {"warp", to_string(a.warp)}});
    }
    j["axes"] = axes;
    j["layout"] = t.axes.size() > 2
                      ? "x: axis 0 along the row; rows: axis 1; axis 2 slices stacked "
                        "vertically (row = z * count_y + y)"
                      : (t.axes.size() == 2 ? "x: axis 0 along the row; rows: axis 1"
                                            : "x: axis 0 along the single row");
    j["channels"] = t.channels;
    j["method"] = t.method;
    j["pixel"] = to_string(s);
    j["error_bound"] = error_bound(t, s);
    return j;
}

std::vector<Axis> axes_from_json(const nlohmann::json& axes) {
    if (!axes.is_array() || axes.empty() || axes.size() > 3)
        throw RuntimeError("metadata 'axes' must be a list of 1 to 3 axes");
    std::vector<Axis> out;
    for (const auto& a : axes) {
        try {
            Axis ax;
            ax.name = a.at("name").get<std::string>();
            ax.min = a.at("min").get<double>();
            ax.max = a.at("max").get<double>();
            ax.count = a.at("count").get<int>();
            ax.placement = placement_from_string(a.at("placement").get<std::string>());
            ax.warp = warp_from_string(a.at("warp").get<std::string>());
            ax.validate();
            out.push_back(ax);
        } catch (const nlohmann::json::exception& e) {
            throw RuntimeError(std::string("metadata axis is malformed: ") + e.what());
        } catch (const Error& e) {
            throw RuntimeError(std::string("metadata axis is malformed: ") + e.what());
        }
    }
    return out;
}

}  // namespace brdflut
