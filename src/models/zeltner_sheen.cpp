#include "brdflut/zeltner_sheen.h"

#include <algorithm>
#include <cmath>

namespace brdflut {

double FibreSggx::projected_area(const Vec3& w) const {
    return std::sqrt(std::max(0.0, w.x * w.x + w.y * w.y + sigma * sigma * w.z * w.z));
}

double FibreSggx::D(double z) const {
    const double s2 = sigma * sigma;
    const double q = s2 * (1.0 - z * z) + z * z;
    return s2 * sigma / (kPi * q * q);
}

double FibreSggx::total() const {
    const double c = std::sqrt((1.0 - sigma) * (1.0 + sigma));
    return 2.0 * (sigma + (c > 0.0 ? std::atan(c / sigma) / c : 1.0 / sigma));
}

double FibreSggx::sample_cos_theta(double u) const {
    const double c2 = (1.0 - sigma) * (1.0 + sigma), c = std::sqrt(c2);
    // The antiderivative of 2 pi D: sigma t / (sigma^2 + c^2 t^2) + atan(c t / sigma) / c.
    auto F = [&](double t) {
        return sigma * t / (sigma * sigma + c2 * t * t) + (c > 0.0 ? std::atan(c * t / sigma) / c : t / sigma);
    };
    const double target = F(-1.0) + u * total();
    double lo = -1.0, hi = 1.0;
    for (int it = 0; it < 64; ++it) {
        const double mid = 0.5 * (lo + hi);
        (F(mid) < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

std::array<double, 2> zeltner_ms_fit(double sigma) {
    static constexpr double m[11] = {20.0, 10.2, 6.14, 4.30, 3.30, 2.55, 2.02, 1.63, 1.33, 1.1, 0.95};
    static constexpr double b[11] = {3.7, 2.23, 1.06, 0.293, -0.212, -0.641, -0.952, -1.2, -1.4, -1.55, -1.65};
    // Knot k at sigma = k/10; knots -1 and 11 continue the end segments linearly.
    auto knot = [](const double* v, int k) {
        if (k < 0) return 2.0 * v[0] - v[1];
        if (k > 10) return 2.0 * v[10] - v[9];
        return v[k];
    };
    const double r = std::clamp(sigma, 0.0, 1.0) * 10.0;
    const int i = std::min(static_cast<int>(std::floor(r)), 9);
    const double t = r - i;
    // Catmull-Rom between knots i and i + 1.
    auto spline = [&](const double* v) {
        const double p0 = knot(v, i - 1), p1 = knot(v, i), p2 = knot(v, i + 1), p3 = knot(v, i + 2);
        return p1 + 0.5 * t * ((p2 - p0) + t * ((2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) + t * (3.0 * (p1 - p2) + p3 - p0)));
    };
    return {spline(m), spline(b)};
}

ZeltnerApproxSheenLobe::ZeltnerApproxSheenLobe(double alpha) : alpha_(alpha), sggx_{alpha * alpha} {
    const auto [m, b] = zeltner_ms_fit(sggx_.sigma);
    m_ = m;
    b_ = b;
    beta_ = std::max(0.55, 0.44 + 0.42 * sggx_.sigma);
}

std::array<double, 2> ZeltnerApproxSheenLobe::terms(const Vec3& wo, const Vec3& wi) const {
    const double mu_o = wo.z, mu_i = wi.z;
    if (!(mu_o > 0.0) || !(mu_i > 0.0)) return {0.0, 0.0};
    const double s_o = sggx_.projected_area(wo), s_i = sggx_.projected_area(wi);
    const Vec3 h{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
    const double len = std::sqrt(dot(h, h));
    // Optical depth of the two paths; -expm1 keeps 1 - exp(-x) accurate for small x.
    const double depth = s_o / mu_o + s_i / mu_i;
    const double ss = sggx_.D(h.z / len) * -std::expm1(-depth) / (4.0 * (s_o * mu_i + s_i * mu_o));
    auto transmission = [&](double c) {
        const double u = 1.0 - c, u2 = u * u, u4 = u2 * u2;
        return beta_ + (1.0 - beta_) * (1.0 - u4 * u4 * u4);
    };
    const double ms = std::exp(b_ - m_ * std::sqrt(mu_o * mu_o + mu_i * mu_i)) * transmission(mu_o) * transmission(mu_i);
    return {ss, ms};
}

LobeSample ZeltnerApproxSheenLobe::sample(const Vec3& wo, double u1, double u2) const {
    return cosine_and_mirror_mixture(
        wo, u1, u2,
        [&](double u, double phi) {
            const double z = sggx_.sample_cos_theta(u), st = safe_sqrt(1.0 - z * z);
            const Vec3 m{st * std::cos(phi), st * std::sin(phi), z};
            // D is even: the flake seen from wo.
            return dot(wo, m) < 0.0 ? Vec3{-m.x, -m.y, -m.z} : m;
        },
        // m and -m both reach h.
        [&](const Vec3& h) { return 2.0 * sggx_.D(h.z) / sggx_.total(); });
}

double ZeltnerApproxSheenLobe::f(const Vec3& wo, const Vec3& wi) const {
    const auto t = terms(wo, wi);
    return t[0] + t[1];
}

}  // namespace brdflut
