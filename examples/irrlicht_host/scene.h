#pragma once
// The Irrlicht host's own world, built in code with nothing loaded from disk: a ring track on
// grass under linear fog, crates, an alpha-tested fence (EMT_TRANSPARENT_ALPHA_CHANNEL_REF), an
// alpha-blended billboard (EMT_TRANSPARENT_ALPHA_CHANNEL), a box "car" that drifts round the ring
// and a GUI label. None of it knows the plugin: main.cpp adds the smoke.
#include <irrlicht.h>

/// Where the scripted car is at a time: a drift round the ring, tail out.
struct CarState {
    irr::core::vector3df position;  // centre of the body, world (y up, left-handed, metres)
    irr::core::vector3df heading;   // where the body points (unit, horizontal)
    irr::core::vector3df velocity;  // where it actually goes, m/s (tangent of the ring)
};
CarState carAt(float seconds);

struct Scene {
    irr::scene::ICameraSceneNode* camera = nullptr;
    irr::scene::ISceneNode* car = nullptr;
    irr::gui::IGUIStaticText* label = nullptr;
    irr::video::SColor fogColor;  // also the clear colour, so the fogged far field meets the sky
};

/// Builds the scene into the device's scene manager and GUI environment.
Scene buildScene(irr::IrrlichtDevice* device);
/// Screen rectangle (pixels, top row 0) inside the crate that stands between the camera and the
/// smoke trail: nothing the plugin draws may show there. Valid after a frame was drawn.
irr::core::recti occluderRect(irr::IrrlichtDevice* device, const Scene& scene);
/// Moves the car's node to `car`.
void placeCar(Scene& scene, const CarState& car);
