// The Irrlicht host's world: every texture is generated here, so the example needs no asset.
#include "scene.h"

#include <cmath>
#include <cstdint>
#include <initializer_list>

using namespace irr;

namespace {

constexpr float kRingRadius = 7.0f;    // the car's path, metres
constexpr float kTrackInner = 5.4f, kTrackOuter = 8.6f;
constexpr float kGroundSize = 48.0f;   // the textured ground plane's side
constexpr float kSpeed = 9.0f;         // m/s along the ring
constexpr float kDriftDegrees = 25.0f; // body yawed into the turn: the rear wheels slide out
const core::vector3df kNearCrate(1.0f, 0.0f, -9.6f);  // on the ground, in front of the ring
constexpr float kNearCrateSize = 1.6f;

// A small deterministic hash for texture noise (the same image on every run and machine).
uint32_t hash(uint32_t x, uint32_t y) {
    uint32_t h = x * 374761393u + y * 668265263u;
    h = (h ^ (h >> 13)) * 1274126177u;
    return h ^ (h >> 16);
}
int noise(uint32_t x, uint32_t y, int amplitude) { return int(hash(x, y) % uint32_t(2 * amplitude + 1)) - amplitude; }
u32 clampByte(int v) { return u32(v < 0 ? 0 : v > 255 ? 255 : v); }

template <typename F>
video::ITexture* makeTexture(video::IVideoDriver* driver, const char* name, u32 size, F texel) {
    video::IImage* image = driver->createImage(video::ECF_A8R8G8B8, core::dimension2du(size, size));
    for (u32 y = 0; y < size; ++y)
        for (u32 x = 0; x < size; ++x) image->setPixel(x, y, texel(x, y));
    video::ITexture* texture = driver->addTexture(name, image);
    image->drop();
    return texture;
}

// Ground: asphalt ring with white edge lines on noisy grass, one texel = kGroundSize / 512 m.
video::SColor groundTexel(u32 x, u32 y) {
    const float s = kGroundSize / 512.0f;
    const float wx = (float(x) + 0.5f) * s - 0.5f * kGroundSize, wz = (float(y) + 0.5f) * s - 0.5f * kGroundSize;
    const float r = std::sqrt(wx * wx + wz * wz);
    const int n = noise(x, y, 10);
    if (std::fabs(r - kTrackInner) < 0.12f || std::fabs(r - kTrackOuter) < 0.12f) return video::SColor(255, 225, 225, 220);
    if (r > kTrackInner && r < kTrackOuter) {
        const u32 g = clampByte(78 + n);
        return video::SColor(255, g, g, clampByte(82 + n));
    }
    return video::SColor(255, clampByte(60 + n), clampByte(110 + n), clampByte(45 + n / 2));
}

// Fence: vertical boards with gaps and two rails; alpha 0 in the gaps (alpha-tested away).
video::SColor fenceTexel(u32 x, u32 y) {
    const bool board = (x % 16) < 11, rail = (y % 32) >= 6 && (y % 32) < 11;
    if (!board && !rail) return video::SColor(0, 0, 0, 0);
    const int n = noise(x / 2, y, 12);
    return video::SColor(255, clampByte(150 + n), clampByte(105 + n), clampByte(60 + n));
}

// Billboard: a round sign whose alpha falls off to its rim (alpha-blended, not tested).
video::SColor signTexel(u32 x, u32 y) {
    const float dx = (float(x) - 31.5f) / 32.0f, dy = (float(y) - 31.5f) / 32.0f;
    const float d = std::sqrt(dx * dx + dy * dy);
    const u32 a = clampByte(int(255.0f * (1.0f - d) * 1.6f));
    const bool ring = d > 0.55f && d < 0.7f;
    return ring ? video::SColor(a, 250, 250, 250) : video::SColor(a, 240, 130, 30);
}

video::SColor crateTexel(u32 x, u32 y) {
    const bool edge = x < 4 || y < 4 || x > 59 || y > 59 || x == y || x + y == 63;
    const int n = noise(x, y, 8);
    return edge ? video::SColor(255, clampByte(95 + n), clampByte(65 + n), clampByte(35 + n))
                : video::SColor(255, clampByte(170 + n), clampByte(130 + n), clampByte(80 + n));
}

video::SColor carTexel(u32, u32 y) {
    return y > 20 && y < 30 ? video::SColor(255, 40, 50, 70) : video::SColor(255, 200, 30, 30);
}

void setCommon(scene::ISceneNode* node, video::ITexture* texture) {
    node->setMaterialTexture(0, texture);
    node->setMaterialFlag(video::EMF_LIGHTING, false);
    node->setMaterialFlag(video::EMF_FOG_ENABLE, true);
}

}  // namespace

CarState carAt(float seconds) {
    const float angle = -1.9f + seconds * kSpeed / kRingRadius;  // starts left of the camera
    CarState car;
    car.position = core::vector3df(kRingRadius * std::cos(angle), 0.75f, kRingRadius * std::sin(angle));
    const core::vector3df tangent(-std::sin(angle), 0.0f, std::cos(angle));  // counter-clockwise from above
    car.velocity = tangent * kSpeed;
    // Yaw the body toward the centre (the turn's inside): the tail swings out.
    const float drift = kDriftDegrees * core::DEGTORAD;
    const core::vector3df inward(-std::cos(angle), 0.0f, -std::sin(angle));
    car.heading = (tangent * std::cos(drift) + inward * std::sin(drift)).normalize();
    return car;
}

Scene buildScene(IrrlichtDevice* device) {
    video::IVideoDriver* driver = device->getVideoDriver();
    scene::ISceneManager* smgr = device->getSceneManager();
    Scene s;
    s.fogColor = video::SColor(255, 170, 185, 200);
    driver->setFog(s.fogColor, video::EFT_FOG_LINEAR, 18.0f, 55.0f, 0.0f, true, false);

    scene::IMesh* ground = smgr->getGeometryCreator()->createPlaneMesh(core::dimension2df(kGroundSize, kGroundSize));
    setCommon(smgr->addMeshSceneNode(ground), makeTexture(driver, "ground", 512, groundTexel));
    ground->drop();
    // A far grass field under the fog, so the horizon is not the clear colour's edge.
    scene::IMesh* field = smgr->getGeometryCreator()->createPlaneMesh(core::dimension2df(400.0f, 400.0f));
    scene::ISceneNode* fieldNode = smgr->addMeshSceneNode(field, nullptr, -1, core::vector3df(0.0f, -0.02f, 0.0f));
    setCommon(fieldNode, makeTexture(driver, "field", 4, [](u32, u32) { return video::SColor(255, 60, 110, 45); }));
    field->drop();

    video::ITexture* crate = makeTexture(driver, "crate", 64, crateTexel);
    // The first crate stands between the camera and the smoke trail: the smoke must be hidden there.
    const struct { float x, z, size; } crates[] = {{kNearCrate.X, kNearCrate.Z, kNearCrateSize}, {-9.6f, -1.0f, 1.8f},
                                                   {4.0f, 0.5f, 1.6f}, {-1.0f, 9.9f, 2.0f}, {2.6f, -4.3f, 1.2f}};
    for (const auto& c : crates) {
        scene::ISceneNode* box = smgr->addCubeSceneNode(c.size, nullptr, -1, core::vector3df(c.x, 0.5f * c.size, c.z));
        setCommon(box, crate);
    }

    scene::IMesh* fenceMesh = smgr->getGeometryCreator()->createPlaneMesh(
        core::dimension2df(9.0f, 2.0f), core::dimension2du(1, 1), nullptr, core::dimension2df(4.5f, 1.0f));
    scene::ISceneNode* fence = smgr->addMeshSceneNode(fenceMesh, nullptr, -1, core::vector3df(-5.0f, 1.0f, -10.0f),
                                                      core::vector3df(-90.0f, 0.0f, 0.0f));
    setCommon(fence, makeTexture(driver, "fence", 64, fenceTexel));
    fence->setMaterialType(video::EMT_TRANSPARENT_ALPHA_CHANNEL_REF);
    fence->setMaterialFlag(video::EMF_BACK_FACE_CULLING, false);
    fenceMesh->drop();

    scene::IBillboardSceneNode* sign =
        smgr->addBillboardSceneNode(nullptr, core::dimension2df(2.6f, 2.6f), core::vector3df(5.5f, 3.2f, 5.5f));
    setCommon(sign, makeTexture(driver, "sign", 64, signTexel));
    sign->setMaterialType(video::EMT_TRANSPARENT_ALPHA_CHANNEL);

    s.car = smgr->addCubeSceneNode(1.0f);
    s.car->setScale(core::vector3df(1.8f, 1.0f, 4.2f));
    setCommon(s.car, makeTexture(driver, "car", 32, carTexel));

    s.camera = smgr->addCameraSceneNode(nullptr, core::vector3df(0.0f, 5.0f, -18.0f), core::vector3df(0.0f, 0.5f, 0.0f));
    s.camera->setNearValue(0.1f);
    s.camera->setFarValue(300.0f);
    s.camera->setFOV(55.0f * core::DEGTORAD);

    const core::dimension2du size = driver->getScreenSize();
    const core::recti rect(8, s32(size.Height) - 26, 8 + 200, s32(size.Height) - 8);
    s.label = device->getGUIEnvironment()->addStaticText(L"Irrlicht 1.8 + CubeFx smoke", rect, true, false, nullptr, -1, true);
    s.label->setBackgroundColor(video::SColor(255, 30, 30, 36));  // opaque: no smoke shows through
    s.label->setOverrideColor(video::SColor(255, 255, 230, 120));
    return s;
}

core::recti occluderRect(IrrlichtDevice* device, const Scene& scene) {
    scene::ISceneCollisionManager* collision = device->getSceneManager()->getSceneCollisionManager();
    const float h = 0.5f * kNearCrateSize, inset = 0.3f * h;  // the middle of the front face
    core::recti r(INT32_MAX, INT32_MAX, INT32_MIN, INT32_MIN);
    for (float dx : {-h + inset, h - inset})
        for (float y : {inset, 2.0f * h - inset}) {
            const core::vector3df corner(kNearCrate.X + dx, y, kNearCrate.Z - h);
            r.addInternalPoint(collision->getScreenCoordinatesFrom3DPosition(corner, scene.camera));
        }
    return r;
}

void placeCar(Scene& scene, const CarState& car) {
    scene.car->setPosition(car.position);
    scene.car->setRotation(car.heading.getHorizontalAngle());
}
