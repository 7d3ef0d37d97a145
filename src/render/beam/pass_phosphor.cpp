#include <algorithm>
#include <cmath>

#include "render/passes.h"

namespace bz::render {

namespace {

// MAME's BGFX path caps the frame time its phosphor decays by; so does this one, so a stall
// (a breakpoint, a slow level load) fades the picture rather than jumping.
constexpr double kMaxDtSeconds = 0.25;

}  // namespace

// Phosphor persistence (shaders/beam/phosphor.glsl): the composite reads this frame's beam image
// and updates the picture (FrameHistory::phosphor) in place, which is then the frame's picture
// (held frames show it, tests read it). The glow fades alike (pass_bloom.cpp).
PhosphorStep phosphor_step(const PassContext& ctx, double dt_seconds) {
    const BeamSettings& b = ctx.settings.beam;
    // Time running backwards (a replay restarted) or a new target: start from black.
    const double dt = dt_seconds < 0.0 ? kMaxDtSeconds : std::min(dt_seconds, kMaxDtSeconds);
    const double tau = std::max(static_cast<double>(b.persistence_ms), 1e-3) * 1e-3;
    const double p = std::max(static_cast<double>(b.power_law_exponent), 0.1);
    // Power law: (1 + t/t0)^-p is half at t = persistence, so t0 = persistence / (2^(1/p) - 1).
    const double t0 = tau / (std::pow(2.0, 1.0 / p) - 1.0);
    PhosphorStep s;
    s.power_law = b.phosphor == PhosphorDecay::power_law;
    s.dt = static_cast<float>(dt);
    s.exp_factor = static_cast<float>(std::exp(-dt / tau));
    s.t0_inv = static_cast<float>(1.0 / t0);
    s.exponent = static_cast<float>(p);
    // The power law's step depends on each pixel's age, which the glow does not keep: it fades
    // with the same half-life instead (half at `persistence`, as the power law is).
    s.glow_factor = static_cast<float>(s.power_law ? std::exp2(-dt / tau) : std::exp(-dt / tau));
    return s;
}

void set_phosphor_uniforms(const gl::Program& program, const PhosphorStep& step) {
    program.set("u_dt", step.dt);
    program.set("u_exp_factor", step.exp_factor);
    program.set("u_t0_inv", step.t0_inv);
    program.set("u_exponent", step.exponent);
}

}  // namespace bz::render
