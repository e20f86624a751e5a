// A table of the directional albedo E(mu, p) of one lobe (lobe_integrals.h),
// or of its average E_avg(p); shared by the Disney and Oren-Nayar families.
#pragma once

#include <string>
#include <vector>

#include "brdflut/catalogue.h"
#include "brdflut/lobe_integrals.h"

namespace brdflut::tables {

enum class LobeTableKind {
    albedo,          // axes: cos_theta, then the lobe's parameter
    albedo_1d,       // axis: cos_theta (a lobe without parameter)
    albedo_average,  // axis: the lobe's parameter
};

// An axis over [0, 1], cell centres, linear, 128 texels by default.
inline AxisSpec unit_axis(std::string name, std::string meaning, int count = 128) {
    return {Axis{std::move(name), 0.0, 1.0, count, Placement::center, Warp::linear}, 0.0, 1.0,
            std::move(meaning)};
}

// model: the metadata describing the lobe (every parameter that changes values).
TableDefinition lobe_table(Lobe lobe, LobeTableKind kind, std::string id, std::string description,
                           std::vector<AxisSpec> axes, std::string channel, nlohmann::json model);

}  // namespace brdflut::tables
