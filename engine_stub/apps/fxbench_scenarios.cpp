#include "fxbench_scenarios.h"

#include "fxbench_options.h"
#include "gl/Paths.h"

namespace fxbench {

void donutCamera(Scenario* s) {
    // The donut (drive t = 4..9 s) spins about the front axle at (-6.15, 0, 0); the car reaches
    // ~3.6 m from it and the smoke drifts towards +Z. This eye stands on the right-hand kerb,
    // 8 m from the pivot and 4 m up, downwind, looking back across the donut.
    s->fixedCamera = true;
    s->eye[0] = -6.15f, s->eye[1] = 4.0f, s->eye[2] = 8.0f;
    s->target[0] = -6.15f, s->target[1] = 1.0f, s->target[2] = 0.0f;
}

const std::vector<Scenario>& allScenarios() {
    static const std::vector<Scenario> scenarios = [] {
        std::vector<Scenario> v;
        Scenario standard;
        standard.name = "standard";
        standard.description =
            "race scene, chase camera, shipped reactions (reactions/*.yaml); drive starts at t=4.0 s "
            "(burnout donut, rear wheels spinning), 1.5 s simulated unrendered to build the smoke, "
            "then warm-up and timed frames from t=5.5 s";
        v.push_back(standard);

        Scenario fill = standard;
        fill.name = "fill";
        fill.description =
            "fill-rate bound: fixed camera on the kerb 4 m up, 8 m downwind of the burnout donut's pivot; bench reaction "
            "data/bench/fill_smoke.yaml (dense 2-9 m puffs, ~1100 alive) so smoke covers most of the "
            "screen; same drive times as standard";
        fill.reactions = cube::paths::data() + "/bench/fill_smoke.yaml";
        fill.prerollSeconds = 2.5;  // timed frames from t = 6.5 s: the donut at full spin
        donutCamera(&fill);
        v.push_back(fill);

        Scenario overdraw = standard;
        overdraw.name = "overdraw";
        overdraw.description =
            "standard plus 8 opaque panels with a costly shader (24 noise octaves) stacked back to front "
            "over the upper 70% of the chase view: overdraw where prepass-EQUAL can pay";
        overdraw.overdrawLayers = 8;
        overdraw.overdrawCost = 24;
        v.push_back(overdraw);

        Scenario empty = standard;
        empty.name = "empty";
        empty.description =
            "standard drive with reactions/none.yaml (no reactions): every mode must cost what nofx costs";
        empty.reactions = cube::paths::reactions() + "/none.yaml";
        v.push_back(empty);
        return v;
    }();
    return scenarios;
}

const Scenario* findScenario(const std::string& name) {
    for (const Scenario& s : allScenarios())
        if (name == s.name) return &s;
    return nullptr;
}

std::string scenarioNameList() {
    std::string s;
    for (const Scenario& sc : allScenarios()) s += (s.empty() ? "" : ", ") + std::string(sc.name);
    return s;
}

cube::Options gameOptions(const Scenario& scenario, const BenchOptions& bench) {
    cube::Options o;
    o.width = bench.width;
    o.height = bench.height;
    o.fixedDt = 1.0 / 60.0;
    o.startTime = scenario.startTime;
    o.seed = bench.seed;
    o.backend = bench.backend;
    o.reactions = scenario.reactions;
    o.hud = false;  // its text names the mode: it would differ between modes
    o.mirror = bench.mirror;
    o.overdrawLayers = scenario.overdrawLayers;
    o.overdrawCost = scenario.overdrawCost;
    o.fixedCamera = scenario.fixedCamera;
    for (int i = 0; i < 3; ++i) {
        o.cameraEye[i] = scenario.eye[i];
        o.cameraTarget[i] = scenario.target[i];
    }
    return o;
}

}  // namespace fxbench
