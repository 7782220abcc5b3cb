#include "fxbench_scenarios.h"

#include <algorithm>

#include "fxbench_named.h"
#include "fxbench_options.h"
#include "gl/Paths.h"

namespace fxbench {

void donutCamera(Scenario* s) {
    // The donut (drive t = 4..9 s) spins about the front axle at (-6.15, 0, 4) (Vehicle.cpp:
    // kX4 + kFrontAxle, kLane); the car reaches ~3.6 m from it and the smoke spreads towards the
    // barrier at z = 8.5. This eye stands behind the barrier, 7 m from the pivot and 3.5 m up,
    // looking back across the donut through the cloud.
    s->fixedCamera = true;
    s->eye[0] = -6.15f, s->eye[1] = 3.5f, s->eye[2] = 11.0f;
    s->target[0] = -6.15f, s->target[1] = 1.0f, s->target[2] = 4.0f;
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
            "fill-rate bound: fixed camera behind the barrier, 3.5 m up and 7 m from the burnout donut's pivot; bench reaction "
            "data/bench/fill_smoke.yaml (1.5-7 m puffs, ~250 alive) so smoke covers most of the screen in "
            "many layers; timed frames from t=6.5 s (2.5 s simulated unrendered)";
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

const Scenario* findScenario(const std::string& name) { return findNamed(allScenarios(), name); }

std::string scenarioNameList() { return namedList(allScenarios()); }

cube::CameraQuads cameraQuads(const Scenario& scenario) {
    // `overdrawLayers` opaque panels facing the camera from 40 m down to 20 m, drawn back to
    // front (the worst order for depth test LESS) over the upper 70 % of the view.
    cube::CameraQuads q;
    q.cost = scenario.overdrawCost;
    const int layers = scenario.overdrawLayers;
    for (int i = 0; i < layers; ++i) {
        cube::CameraQuad p;
        p.distance = 40.0f - 20.0f * float(i) / float(std::max(1, layers - 1));
        p.centerY = 0.3f;
        p.halfWidth = 0.95f;
        p.halfHeight = 0.7f;
        p.color = glm::vec4(0.3f + 0.05f * float(i % 8), 0.35f, 0.5f - 0.03f * float(i % 8), 1.0f);
        q.quads.push_back(p);
    }
    return q;
}

cube::Options gameOptions(const Scenario& scenario, const BenchOptions& bench) {
    cube::Options o;
    o.width = bench.width;
    o.height = bench.height;
    o.fixedDt = 1.0 / 60.0;
    o.startTime = scenario.startTime;
    o.seed = bench.seed;
    o.backend = bench.backend;
    o.reversedZ = bench.reversedZ;
    o.threads = bench.threads;
    o.reactions = scenario.reactions;
    o.hud = false;  // its text names the mode: it would differ between modes
    // Modes are interleaved frame by frame: keep every mode's targets alive across a whole round
    // so no timed render pays for re-creating targets another mode's frames let expire.
    o.poolFramesUntilFree = 64;
    o.mirror = bench.mirror;
    o.fixedCamera = scenario.fixedCamera;
    for (int i = 0; i < 3; ++i) {
        o.cameraEye[i] = scenario.eye[i];
        o.cameraTarget[i] = scenario.target[i];
    }
    return o;
}

}  // namespace fxbench
