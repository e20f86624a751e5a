// Identifying a table of unknown convention: which catalogue table it holds
// and in which layout (`brdflut identify`).
//
// The search runs over every catalogue table with the file's number of axes
// (presets included; not the per-texel fits, see
// TableDefinition::searched_by_identify), each option with a fixed list of values (GGX
// `visibility`), and the axis vocabulary of axis.h: storage order, per axis
// placement, every registered warp valid on the table's default range, that
// range forward and reversed, flip, shifts of +-0.5 and +-1 texel (clamped to
// the domain when they leave it), clamps at a grid end that reaches the
// domain's lower end, what each file channel holds (a table channel, a sum of
// two, or constant 0 or 1 padding after the last compared channel) and the
// value transform (none, or the sRGB EOTF of the values).
//
// 1. Coarse: each table is tabulated once at draft quality on a dense
//    end-point grid of its default axes and interpolated (cubic, in the
//    default axes' normalized coordinate) at about 8 x 8 texels of the file,
//    edges included. Axis descriptions that give the same parameters at every
//    texel are kept once, in their simplest form; layouts that change more
//    than 4 fields of the default axes (placement, warp, range, flip, clamp
//    count 1 each, a shift 2) are not searched.
// 2. Refinement: the best few dozen, with the clamp variants, are evaluated
//    exactly (the table's evaluator, default quality) at up to 12 x 12 texels.
// 3. Final: the best `top` are generated in full and scored with
//    compare_values, so their figures and verdicts are those of `brdflut
//    compare` with the printed arguments.
//
// A flat array (one row, as a source array of one dimension reads) is
// searched as it is (1-D tables) and as every factorization W x H of its
// length with W, H >= 4 (2-D tables); the explanations of all are ranked
// together, and the compare line of a 2-D one adds --size when the shape is
// not the table's default.
//
// The result does not depend on the thread count.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "brdflut/exr.h"
#include "brdflut/lut.h"

namespace brdflut {

struct IdentifyOptions {
    int top = 3;      // explanations to return (1 to 50)
    int threads = 0;  // 0: every core
};

struct Explanation {
    LutDescription description;  // table, settings (axes in storage order, channel map, options), values
    // Over every value compare checks (padding channels excluded), from the
    // exact values at every texel.
    double max_error = 0.0;
    double rms_error = 0.0;
    bool pass = false;  // compare's verdict with the file's default tolerance
    Tolerance tolerance;
    // File channels read as constant padding (not compared), as "B = 0".
    std::vector<std::string> padding;
    // Plain statements of how the layout differs from the table's own
    // default, each naming the bug pattern it matches.
    std::vector<std::string> findings;
    // How many fields of the layout differ from the table's default (ties
    // in error rank the simpler first).
    int cost = 0;
    // The arguments that make `brdflut compare FILE` check this description.
    std::string compare_arguments;
    // A flat array read as this 2-D shape ("32x32"); empty otherwise.
    std::string flat_shape;
};

struct IdentifyReport {
    std::vector<Explanation> explanations;  // best first: smallest max error, then rms (to 3 digits), then simplest
    std::size_t tables = 0;                 // table and option combinations searched
    std::size_t coarse_candidates = 0;      // layouts scored on the coarse subset
    std::size_t refined_candidates = 0;     // layouts evaluated exactly on the refinement subset
};

// Throws Error for options out of range, RuntimeError when no catalogue
// table has the file's number of axes.
IdentifyReport identify(const ExrImage& img, const IdentifyOptions& options = {});

// The `brdflut compare` arguments (after the file name) that describe d for
// an image of img's size and channels: --as and every field that differs
// from the table's default.
std::string compare_arguments(const LutDescription& d, const ExrImage& img);

// How d's layout differs from its table's default, as plain statements.
std::vector<std::string> describe_findings(const LutDescription& d);

}  // namespace brdflut
