#include "fxbench_integrators.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/glm.hpp>

// The plugin's integrators are internal to fx_plugin (no public header): fxbench reaches the
// header by path, and links the functions through fx_plugin as engine_stub does.
#include "sim/Integrator.h"

namespace fxbench {

namespace {

using StepFn = void (*)(glm::vec3&, glm::vec3&, glm::vec3, float, float);

struct Method {
    const char* name;
    StepFn step;
};

const Method kMethods[] = {
    {"explicit Euler", fx::stepExplicitEuler},
    {"semi-implicit Euler", fx::stepSemiImplicitEuler},
    {"exact (fx::stepExact)", fx::stepExact},
};

// A puff leaving a spinning wheel: 4 m/s sideways and 1 m/s up, relaxing to the burnout
// reaction's terminal velocity (wind 0.5 m/s along x, rise 0.45 m/s).
const glm::vec3 kX0(0.0f), kV0(4.0f, 1.0f, 0.0f), kU(0.5f, 0.45f, 0.0f);

/// |x_numeric(T) - x_exact(T)| in metres after steps of dt covering T (the last step shortened).
double positionError(StepFn step, float k, double dt, double T) {
    glm::vec3 x = kX0, v = kV0;
    double t = 0.0;
    while (t < T - 1e-12) {
        const double h = std::min(dt, T - t);
        step(x, v, kU, k, float(h));
        t += h;
    }
    glm::dvec3 xe, ve;
    fx::exactSolution(glm::dvec3(kX0), glm::dvec3(kV0), glm::dvec3(kU), double(k), T, &xe, &ve);
    return glm::length(glm::dvec3(x) - xe);
}

std::string cell(double e) {
    char b[48];
    if (!std::isfinite(e) || e > 1e30) return "diverged";
    std::snprintf(b, sizeof b, "%.3g", e);
    return b;
}

/// CPU ms per million particle updates: a 4096-particle SoA-like array, stepped repeatedly.
template <class Fn>
double msPerMillion(Fn&& stepAll, int particles) {
    using Clock = std::chrono::steady_clock;
    int steps = 1;
    for (;;) {
        const auto t0 = Clock::now();
        for (int s = 0; s < steps; ++s) stepAll();
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        if (ms > 150.0 || steps > (1 << 20)) return ms / (double(steps) * particles / 1e6);
        steps *= 2;
    }
}

}  // namespace

std::string integratorReport() {
    std::string o;
    char line[512];
    o += "## fxbench --integrators\n\n";
    o += "dv/dt = -k (v - u), x0 = 0, v0 = (4, 1, 0) m/s, u = (0.5, 0.45, 0) m/s; error = |x(T) - x_exact(T)| in "
         "metres (steppers in float, analytic reference in double: fx::exactSolution)\n\n";

    const double T1 = 2.0;
    const float k1 = 1.2f;
    std::snprintf(line, sizeof line, "### Burnout drag k = %.1f /s, T = %.0f s\n\n", double(k1), T1);
    o += line;
    o += "| dt (s) | k*dt |";
    for (const Method& m : kMethods) o += std::string(" ") + m.name + " |";
    o += "\n|---|---:|---:|---:|---:|\n";
    const double dts[] = {1.0 / 240, 1.0 / 120, 1.0 / 60, 1.0 / 30, 0.1, 0.25, 0.5, 1.0};
    const char* dtNames[] = {"1/240", "1/120", "1/60", "1/30", "0.1", "0.25", "0.5", "1"};
    for (size_t i = 0; i < sizeof dts / sizeof dts[0]; ++i) {
        std::snprintf(line, sizeof line, "| %s | %.3g |", dtNames[i], double(k1) * dts[i]);
        o += line;
        for (const Method& m : kMethods) o += " " + cell(positionError(m.step, k1, dts[i], T1)) + " |";
        o += "\n";
    }

    const double dt2 = 1.0 / 60, T2 = 1.0;
    o += "\n### Stiff drag: dt = 1/60 s, T = 1 s (60 steps), k chosen for k*dt\n\n";
    o += "| k*dt | k (/s) |";
    for (const Method& m : kMethods) o += std::string(" ") + m.name + " |";
    o += "\n|---:|---:|---:|---:|---:|\n";
    const double kdts[] = {0.1, 0.5, 1.0, 1.9, 2.0, 2.1, 10.0, 100.0, 1e4};
    for (double kdt : kdts) {
        const float k = float(kdt / dt2);
        std::snprintf(line, sizeof line, "| %g | %.4g |", kdt, double(k));
        o += line;
        for (const Method& m : kMethods) o += " " + cell(positionError(m.step, k, dt2, T2)) + " |";
        o += "\n";
    }
    o += "\nExplicit Euler is unstable for k*dt > 2 (|1 - k dt| > 1); semi-implicit Euler shares its velocity "
         "update, so it diverges there too; the exact step is stable for any k*dt.\n";

    // CPU cost.
    constexpr int kN = 4096;
    std::vector<glm::vec3> xs(kN, kX0), vs(kN, kV0);
    for (int i = 0; i < kN; ++i) vs[size_t(i)] += glm::vec3(0.001f * float(i % 97), 0.0f, 0.0f);
    const float k = 1.2f, dt = 1.0f / 60.0f;
    auto reset = [&] {
        for (int i = 0; i < kN; ++i) xs[size_t(i)] = kX0, vs[size_t(i)] = kV0;
    };
    o += "\n### CPU cost (this machine, one core, 4096 particles stepped repeatedly, dt = 1/60, k = 1.2)\n\n";
    o += "| method | ms per million particle updates (= ns per update) |\n|---|---:|\n";
    volatile float sink = 0.0f;
    for (const Method& m : kMethods) {
        reset();
        const double ms = msPerMillion(
            [&] {
                for (int i = 0; i < kN; ++i) m.step(xs[size_t(i)], vs[size_t(i)], kU, k, dt);
            },
            kN);
        sink = sink + xs[0].x;
        std::snprintf(line, sizeof line, "| %s | %.2f |\n", m.name, ms);
        o += line;
    }
    reset();
    const double hoisted = msPerMillion(
        [&] {
            const fx::DragStep s = fx::makeDragStep(k, dt);  // once per reaction and frame, as the pool does
            for (int i = 0; i < kN; ++i) fx::applyDragStep(s, kU, xs[size_t(i)], vs[size_t(i)]);
        },
        kN);
    sink = sink + xs[0].x;
    std::snprintf(line, sizeof line, "| exact, coefficients once per frame (fx::applyDragStep: the pool's path) | %.2f |\n",
                  hoisted);
    o += line;
    (void)sink;
    o += "\n(bench_sim measures the whole particle update through "
         "fx::ReactionRuntime against a memory-bandwidth reference.)\n";
    return o;
}

}  // namespace fxbench
