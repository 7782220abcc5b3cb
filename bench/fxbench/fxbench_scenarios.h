#pragma once
// What fxbench renders: the scene, drive time, camera and reactions of each scenario.
#include <string>
#include <vector>

#include "game/Options.h"
#include "render/SceneRenderer.h"

namespace fxbench {

struct BenchOptions;

/// One scenario. Defaults: the standard race scene.
struct Scenario {
    const char* name = "standard";
    const char* description = "";  ///< printed above the table and stored in the JSON
    double startTime = 4.0;        ///< drive time (s) at which the simulation starts
    double prerollSeconds = 1.5;   ///< simulated (not rendered) before warm-up, to build the smoke
    std::string reactions;         ///< empty = reactions/ (every shipped file)
    int overdrawLayers = 0;
    int overdrawCost = 16;
    bool fixedCamera = false;
    float eye[3] = {0, 0, 0};
    float target[3] = {0, 0, 0};
};

/// standard, fill, overdraw, empty.
const std::vector<Scenario>& allScenarios();
const Scenario* findScenario(const std::string& name);
std::string scenarioNameList();

/// The Game options for `scenario` under the bench's flags: fixed dt 1/60, the seed, size,
/// backend, HUD off, mirror as asked.
cube::Options gameOptions(const Scenario& scenario, const BenchOptions& bench);
/// The scenario's overdraw panels as quads on the chase camera (none unless overdrawLayers > 0).
cube::CameraQuads cameraQuads(const Scenario& scenario);

/// The fixed camera the fill scenario and the particle sweep use: low, beside the burnout
/// donut, looking at the pivot the car spins around.
void donutCamera(Scenario* s);

}  // namespace fxbench
