#pragma once
// PCG32 (O'Neill): small, fast and fully specified, so a seed gives the same stream on every
// compiler and platform. The simulation uses only this, never rand() or <random> engines.
#include <cstdint>

namespace bz {

class Rng {
  public:
    explicit Rng(std::uint64_t seed = 0x853c49e6748fea9bull,
                 std::uint64_t stream = 0xda3e39cb94b95bdbull)
        : state_(0), inc_((stream << 1u) | 1u) {
        next_u32();
        state_ += seed;
        next_u32();
    }
    std::uint32_t next_u32() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    // Uniform in [0, 1).
    double uniform() { return next_u32() * (1.0 / 4294967296.0); }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Uniform integer in [0, n); n > 0.
    std::uint32_t below(std::uint32_t n) {
        const std::uint32_t threshold = (0u - n) % n;
        for (;;) {
            const std::uint32_t r = next_u32();
            if (r >= threshold) return r % n;
        }
    }
    std::uint64_t state() const { return state_; }
    std::uint64_t increment() const { return inc_; }

  private:
    std::uint64_t state_;
    std::uint64_t inc_;
};

}  // namespace bz
