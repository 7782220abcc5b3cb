#pragma once
// Frame-rate-independent emission for one source (one wheel, say). The source accumulates
// rate * dt particles and releases the whole ones, carrying the fraction to the next step, so
// one simulated second at rate r emits r particles (within 1) whether it is taken in 30 steps
// or 300. Each released particle also gets the exact instant it was due inside the step: the
// caller ages it by that much, so particles of one step are spread along the step instead of
// bunching at its end (the startup artefact of 002 section 2.4).
#include <cmath>
#include <cstdint>

namespace fx {

class EmissionClock {
public:
    /// Advances by `dt` seconds at `rate` particles/s. Returns how many particles fell due.
    /// A rate or dt that is not finite and positive releases nothing and keeps the carry.
    int64_t advance(double rate, double dt) {
        before_ = carry_;
        rate_ = 0.0;
        dt_ = 0.0;
        if (!(rate > 0.0) || !(dt > 0.0) || !std::isfinite(rate) || !std::isfinite(dt)) return 0;
        rate_ = rate;
        dt_ = dt;
        const double total = carry_ + rate * dt;
        if (total >= kMaxDue) {
            // An absurd hitch: only its last kMaxDue / rate seconds count (a particle due before
            // them is long dead), so the count and every k below it stay far inside int64_t.
            carry_ = before_ = 0.0;
            dt_ = kMaxDue / rate;
            return static_cast<int64_t>(kMaxDue);
        }
        const double whole = std::floor(total);
        carry_ = total - whole;
        return static_cast<int64_t>(whole);
    }

    /// Seconds before the end of the last advance() at which its k-th (0 = oldest) particle was
    /// due: dt - (k + 1 - carry_before) / rate, in [0, dt].
    double ageOf(int64_t k) const {
        if (rate_ <= 0.0) return 0.0;
        const double age = dt_ - (static_cast<double>(k) + 1.0 - before_) / rate_;
        return age < 0.0 ? 0.0 : age;
    }

    /// The first k of the last advance() whose age is below `maxAge`: older ones would be dead
    /// on arrival, so a long hitch costs at most (maxAge * rate) spawns, not (dt * rate).
    /// Never above kMaxDue, the most advance() returns: a value past int64_t's range is never
    /// converted (that conversion is undefined and read as INT64_MIN, a loop of 2^63 spawns).
    int64_t firstYoungerThan(double maxAge) const {
        if (rate_ <= 0.0) return 0;
        const double x = rate_ * (dt_ - maxAge) + before_ - 1.0;
        if (!(x >= 0.0)) return 0;  // NaN too (a non-finite maxAge)
        if (x >= kMaxDue) return static_cast<int64_t>(kMaxDue);
        return static_cast<int64_t>(std::floor(x)) + 1;
    }

    /// The fraction of a particle carried to the next step, in [0, 1).
    double carry() const { return carry_; }
    void reset() { carry_ = before_ = rate_ = dt_ = 0.0; }

    /// The most particles one advance() releases (and the most firstYoungerThan returns).
    static constexpr double kMaxDue = 1e12;

private:
    double carry_ = 0.0;
    double before_ = 0.0;
    double rate_ = 0.0;
    double dt_ = 0.0;
};

}  // namespace fx
