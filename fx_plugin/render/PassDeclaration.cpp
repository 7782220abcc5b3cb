#include "PassDeclaration.h"

#include <algorithm>
#include <utility>

#include "ImmediateFrame.h"
#include "reactions/TechniqueTable.h"

namespace fx {

void narrowDepthRead(FrameBuilder& frame, const ScreenRect& bound, int width, int height) {
    auto* immediate = dynamic_cast<ImmediateFrame*>(&frame);
    if (!immediate) return;
    DepthRegion r;  // whole
    if (!bound.whole) {
        // A pass reads the scene depth inside its particles' bound, grown by the quarter-res
        // tiles' reach (16 px tiles, 6 px border); whole 64 px blocks, so the region changes
        // only when the bound crosses a block, not with every pixel the smoke moves.
        constexpr int kReach = ScreenTiles::kTileSize + 16, kAlign = 64;
        auto down = [](int v) { return v <= 0 ? 0 : v / kAlign * kAlign; };
        auto up = [](int v, int limit) { return std::min(limit, (v + kAlign - 1) / kAlign * kAlign); };
        r.whole = false;
        r.x0 = down(bound.x0 - kReach);
        r.y0 = down(bound.y0 - kReach);
        r.x1 = up(bound.x1 + kReach, width);
        r.y1 = up(bound.y1 + kReach, height);
    }
    immediate->setNextDepthRegion(r);
}

void addPassReading(FrameBuilder& frame, const char* name, std::initializer_list<Target> maybeReads, Target write,
                    std::function<void(PassContext&)> execute) {
    Target r[4];
    int n = 0;
    for (Target t : maybeReads) {
        if (t.valid() && n < 4) r[n++] = t;
    }
    switch (n) {
    case 0: frame.addPass(name, {}, {write}, std::move(execute)); break;
    case 1: frame.addPass(name, {r[0]}, {write}, std::move(execute)); break;
    case 2: frame.addPass(name, {r[0], r[1]}, {write}, std::move(execute)); break;
    case 3: frame.addPass(name, {r[0], r[1], r[2]}, {write}, std::move(execute)); break;
    default: frame.addPass(name, {r[0], r[1], r[2], r[3]}, {write}, std::move(execute)); break;
    }
}

Footprint footprintOf(const DrawList& list) {
    bool spheres = false;
    for (const DrawBatch& batch : list.batches) spheres = spheres || techniqueRow(batch.technique, false).raySphere;
    return spheres ? Footprint::Box : Footprint::Billboard;
}

}  // namespace fx
