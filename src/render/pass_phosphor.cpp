#include <algorithm>
#include <cmath>

#include "render/passes.h"

namespace bz::render {

namespace {

// MAME's BGFX path caps the frame time its phosphor decays by; so does this one, so a stall
// (a breakpoint, a slow level load) fades the picture rather than jumping.
constexpr double kMaxDtSeconds = 0.25;

}  // namespace

// Phosphor persistence (shaders/phosphor.frag): reads this frame's beam image and the previous
// picture, writes the new picture into the other history texture. Returns the picture, which
// bloom and composite then read instead of the beam image.
const gl::Texture2D& pass_phosphor(const PassContext& ctx, const gl::Texture2D& beam, double dt_seconds) {
    Targets& t = ctx.targets;
    const BeamSettings& b = ctx.settings.beam;
    const int from = t.phosphor_front, to = 1 - t.phosphor_front;
    // Time running backwards (a replay restarted) or a new target: start from black.
    const double dt = dt_seconds < 0.0 ? kMaxDtSeconds : std::min(dt_seconds, kMaxDtSeconds);
    const double tau = std::max(static_cast<double>(b.persistence_ms), 1e-3) * 1e-3;
    const double p = std::max(static_cast<double>(b.power_law_exponent), 0.1);
    // Power law: (1 + t/t0)^-p is half at t = persistence, so t0 = persistence / (2^(1/p) - 1).
    const double t0 = tau / (std::pow(2.0, 1.0 / p) - 1.0);

    t.phosphor_fbo[to].bind();
    gl::apply(gl::PipelineState{});
    const gl::Program& prog = ctx.programs.phosphor;
    prog.use();
    prog.set("u_lines", 0);
    prog.set("u_history", 1);
    prog.set("u_dt", static_cast<float>(dt));
    prog.set("u_power_law", b.phosphor == PhosphorDecay::power_law ? 1 : 0);
    prog.set("u_exp_factor", static_cast<float>(std::exp(-dt / tau)));
    prog.set("u_t0_inv", static_cast<float>(1.0 / t0));
    prog.set("u_exponent", static_cast<float>(p));
    beam.bind(0);
    t.phosphor[from].bind(1);
    ctx.empty_vao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    t.phosphor_front = to;
    return t.phosphor[to];
}

}  // namespace bz::render
