// Separable subsurface-scattering kernels (Jimenez et al. 2015): a radial
// diffusion profile R(r) blurred in screen space by two 1-D passes, along x
// and then along y, with one kernel k, so that the 2-D blur is k(x) k(y).
// The kernel is a set of taps at offsets o (mirrored: -o and o, the centre
// once), each with a weight per colour channel; the weights of one channel
// add to 1 over the mirrored taps.
//
// Jimenez, Zsolnai, Jarabo, Freude, Auzinger, Wu, von der Pahlen, Wimmer and
// Gutierrez 2015, "Separable Subsurface Scattering" (Computer Graphics
// Forum 34(6)); Unreal Engine's ComputeMirroredSSSKernel (SeparableSSS.cpp)
// and ComputeMirroredBSSSKernel (BurleyNormalizedSSS.cpp), which bake such
// kernels per subsurface profile.
//
// The offsets. With n one-sided taps there are 2n - 1 taps at
//   o = radius sign(t) |t|^p,  t = -1 + 2 i / (2n - 2),  i = 0 .. 2n - 2
// (Unreal: p = 2, radius 3 mm when 2n - 1 > 20 and 2 mm otherwise).
//
// The cells. Tap i's cell runs from the midpoint to its inner neighbour to
// the midpoint to its outer neighbour; the centre's is symmetric about 0 and
// the outermost one ends at its tap. Its width is Unreal's "area",
// (|o_i - o_(i-1)| + |o_(i+1) - o_i|) / 2.
//
// The 1-D kernel shape (KernelShape), at |x|:
//   line      R(|x|): the profile along a line through its centre
//             (Jimenez's and Unreal's separable kernel; infinite at 0 for
//             Burley's profile, whose integral across 0 diverges);
//   radial    |x| R(|x|): the radial density 2 pi r R(r) over 2 pi (Unreal's
//             Burley kernel samples this, which Unreal calls the profile);
//   marginal  the integral of R(sqrt(x^2 + y^2)) over y: the profile
//             projected onto a line, which is the blur a straight edge of
//             light gets. A single Gaussian is its own projection, so for
//             one Gaussian the separable product is the profile exactly.
// The weights (KernelWeights):
//   point     the cell's width times the shape at the tap (Unreal's rule);
//   cell      the integral of the shape over the cell.
// Each channel's weights are then divided by their sum over the mirrored
// taps.
//
// The separable error. The 2-D kernel the two passes apply puts w_a w_b at
// the tap pair (a, b); the profile puts the mass P_ab of the cell pair, the
// integral of R over the product of the two cells divided by R's integral
// over the whole square the cells cover. The misplaced energy is the total
// variation distance (1/2) sum over a, b of |w_a w_b - P_ab|: the part of the
// light the separable kernel puts in the wrong cell, 0 when it is the
// profile's own cell masses. The outside energy is the part of the profile's
// reflectance beyond the square, which no tap reaches (the normalization
// spreads it over the taps).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "brdflut/skin.h"

namespace brdflut {

enum class KernelShape { line, radial, marginal };
enum class KernelWeights { point, cell };
std::string_view to_string(KernelShape s);
std::string_view to_string(KernelWeights w);
KernelShape kernel_shape_from_string(std::string_view s);      // throws brdflut::Error
KernelWeights kernel_weights_from_string(std::string_view s);  // throws brdflut::Error

// The n one-sided offsets o_0 = 0 < o_1 < ... < o_(n-1) = radius of the
// rule above (n >= 2, radius > 0, exponent > 0).
std::vector<double> separable_tap_offsets(int one_sided, double radius, double exponent);

// The edges u_0 = 0 < u_1 < ... < u_n of the taps' one-sided cells: tap i > 0
// covers [u_i, u_(i+1)], the centre [-u_1, u_1].
std::vector<double> separable_cell_edges(const std::vector<double>& offsets);

// Why a shape and weight rule cannot be built for a profile ("" when they
// can): Burley's profile is infinite at r = 0, so `line` has no finite
// weights and `marginal` (logarithmically infinite at 0) no point weight.
std::string separable_kernel_refusal(const RadialProfile& p, KernelShape shape, KernelWeights weights);

struct SeparableKernel {
    std::vector<double> offset;                 // the one-sided offsets, in the profile's length unit
    std::vector<std::array<double, 3>> weight;  // per tap and channel: w_0 + 2 sum_(i>0) w_i = 1
    std::vector<std::array<double, 3>> error;   // estimated absolute error of each weight
    long long evaluations = 0;                  // profile evaluations spent
};

// The kernel of a profile per channel at the one-sided offsets; the
// integrals (cell weights, the marginal shape) by adaptive Gauss-Kronrod to
// abs_tol in each weight. Throws brdflut::Error where
// separable_kernel_refusal() gives a reason.
SeparableKernel separable_kernel(const SkinProfile& p, KernelShape shape, KernelWeights weights,
                                 const std::vector<double>& offsets, double abs_tol);

// The marginal shape at x: the integral of R(sqrt(x^2 + y^2)) dy over the
// real line, by adaptive quadrature in y = x sinh(t) (x > 0; at x = 0, twice
// the integral of R over [0, inf)). error: its estimate.
Estimate<1> radial_profile_marginal(const RadialProfile& p, double x, double abs_tol);

struct SeparableError {
    std::array<double, 3> misplaced{};  // (1/2) sum |w_a w_b - P_ab| per channel
    std::array<double, 3> outside{};    // 1 - (R's integral over the square) / (R's total)
    std::array<double, 3> error{};      // estimated absolute error of `misplaced`
    long long evaluations = 0;
};

// The separable error of a kernel against its profile: the cell masses by
// nested adaptive Gauss-Kronrod (x outside, y inside) to abs_tol each.
SeparableError separable_error(const SkinProfile& p, const SeparableKernel& k, double abs_tol);

// The integral of R(sqrt(x^2 + y^2)) over [x0, x1] x [y0, y1] (0 <= x0 < x1,
// 0 <= y0 < y1) by the same nested quadrature: the cell masses of
// separable_error.
Estimate<1> radial_profile_rectangle(const RadialProfile& p, double x0, double x1, double y0, double y1,
                                     double abs_tol);

}  // namespace brdflut
