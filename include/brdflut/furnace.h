// The white-furnace report: the directional albedo of every BRDF model over
// its parameter grid, with F = 1 and unit base colour, and where it leaves
// [0, 1]. `brdflut furnace` prints it; the tests assert the models that are
// meant to conserve energy.
#pragma once

#include <string>
#include <vector>

#include "brdflut/axis.h"

namespace brdflut {

struct FurnaceModel {
    std::string id;           // e.g. "ggx_kulla_conty"
    std::string description;
    std::string albedo_table; // the catalogue table of E(mu[, p])
    std::string average_table;  // the table of E_avg(p), empty if none
    std::vector<std::pair<std::string, std::string>> params;  // model options
    bool kulla_conty = false; // add the Kulla-Conty multiple-scattering lobe
    bool conserves = false;   // meant to return exactly 1
    double tolerance = 0.0;   // allowed |E - 1| when it conserves
    int channel = 0;          // the table channel that holds the albedo
    // Axes held at one value (name, value), e.g. the index of refraction of
    // the glass tables: the report spans cos_theta and one parameter.
    std::vector<std::pair<std::string, double>> fixed = {};
    // Scale E by 1 / E' where E' is the catalogue's table at its default size
    // and float storage, looked up (multi)linearly at the same point, as a
    // renderer that compensates the energy loss with the table does (Cycles'
    // glass). The result is white up to the table's interpolation error.
    bool compensated = false;
};

const std::vector<FurnaceModel>& furnace_models();
const FurnaceModel& find_furnace_model(const std::string& id);  // throws Error listing the ids

struct FurnacePoint {
    double value = 0.0;
    std::vector<double> params;  // axis values
};

struct FurnaceReport {
    const FurnaceModel* model = nullptr;
    std::vector<Axis> axes;      // x = cos_theta, y = the model parameter (if any)
    std::vector<double> albedo;  // E per grid point, x fastest
    FurnacePoint min, max;       // smallest and largest albedo
    FurnacePoint max_excess;     // largest E - 1 (<= 0 when it never exceeds 1)
    FurnacePoint worst_loss;     // largest 1 - E
    std::vector<double> averages;  // E_avg per value of the second axis (or one value)
    double average_min = 0.0, average_max = 0.0;
    double tolerance = 0.0;
    bool pass = true;            // false when a conserving model's |E - 1| > tolerance
};

struct FurnaceOptions {
    int size = 64;          // grid points per axis
    int threads = 0;
    double tolerance = -1;  // < 0: the model's own
};

FurnaceReport run_furnace(const FurnaceModel& model, const FurnaceOptions& opt = {});

}  // namespace brdflut
