#include "ScreenTiles.h"

#include <algorithm>
#include <cmath>

#include "render/PrivateGl.h"

namespace fx {
namespace {

constexpr int kTileSize = ScreenTiles::kTileSize, kTileBorder = ScreenTiles::kTileBorder;

// NDC to pixels.
float toPixel(float ndc, int size) { return (ndc * 0.5f + 0.5f) * float(size); }

// Appends the pixel rectangle [x0, x1) x [y0, y1) as two triangles.
void addRun(ScreenTiles* tiles, int x0, int y0, int x1, int y1) {
    const float a = float(x0), b = float(x1), c = float(y0), d = float(y1);
    const float v[12] = {a, c, b, c, b, d, a, c, b, d, a, d};
    tiles->vertices.insert(tiles->vertices.end(), v, v + 12);
    tiles->pixels += int64_t(x1 - x0) * (y1 - y0);
}

}  // namespace

ScreenRect screenRect(const ViewInfo& view, const ParticleInstance* instances, int count, ScreenTiles* tiles,
                      Footprint footprint) {
    ScreenRect r;
    const int w = view.width, h = view.height;
    const int tilesX = (w + kTileSize - 1) / kTileSize, tilesY = (h + kTileSize - 1) / kTileSize;
    if (tiles) {
        tiles->vertices.clear();
        tiles->pixels = 0;
        tiles->viewWidth = w;
        tiles->viewHeight = h;
        tiles->grid.assign(size_t(std::max(0, tilesX * tilesY)), 0);
    }
    auto wholeView = [&]() {
        if (tiles && w > 0 && h > 0) {
            tiles->vertices.clear();
            tiles->pixels = 0;
            addRun(tiles, 0, 0, w, h);
        }
        return r;  // whole = true
    };
    float lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};
    bool any = false;
    for (int i = 0; i < count; ++i) {
        const ParticleInstance& p = instances[i];
        const glm::vec3 c = glm::vec3(view.view * glm::vec4(p.x, p.y, p.z, 1.0f));
        const float radius = 0.71f * p.size;
        // A billboard lies in the view plane through its centre: its square, no depth extent.
        const float depthExtent = footprint == Footprint::Billboard ? 0.0f : radius;
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) || !std::isfinite(radius)) {
            return wholeView();  // no bound to trust
        }
        if (c.z - depthExtent >= -view.nearPlane) continue;      // wholly behind the near plane: clipped
        if (c.z + depthExtent >= -view.nearPlane) return wholeView();  // reaches the near plane
        float plo[2] = {1e30f, 1e30f}, phi[2] = {-1e30f, -1e30f};
        const int corners = depthExtent > 0.0f ? 8 : 4;  // a flat square has 4
        for (int corner = 0; corner < corners; ++corner) {
            const glm::vec3 q = c + glm::vec3(corner & 1 ? radius : -radius, corner & 2 ? radius : -radius,
                                              corner & 4 ? depthExtent : -depthExtent);
            const glm::vec4 clip = view.proj * glm::vec4(q, 1.0f);
            for (int a = 0; a < 2; ++a) {
                const float ndc = clip[a] / clip.w;
                plo[a] = std::min(plo[a], ndc);
                phi[a] = std::max(phi[a], ndc);
            }
        }
        for (int a = 0; a < 2; ++a) {
            lo[a] = std::min(lo[a], plo[a]);
            hi[a] = std::max(hi[a], phi[a]);
        }
        any = true;
        if (tiles && tilesX > 0 && tilesY > 0) {
            // The particle's pixels grown by the border, as a tile range clamped to the view (the
            // float clamp first: a bound far off screen must not overflow the int).
            auto tileOf = [](float pixel, int border, int tileCount) {
                const float t = std::floor((pixel + float(border)) / float(kTileSize));
                return int(std::min(std::max(t, 0.0f), float(tileCount - 1)));
            };
            const float px0 = toPixel(plo[0], w), px1 = toPixel(phi[0], w);
            const float py0 = toPixel(plo[1], h), py1 = toPixel(phi[1], h);
            if (px1 < -kTileBorder || py1 < -kTileBorder || px0 > w + kTileBorder || py0 > h + kTileBorder) continue;
            const int tx0 = tileOf(px0, -kTileBorder, tilesX), tx1 = tileOf(px1, kTileBorder, tilesX);
            const int ty0 = tileOf(py0, -kTileBorder, tilesY), ty1 = tileOf(py1, kTileBorder, tilesY);
            for (int ty = ty0; ty <= ty1; ++ty) {
                std::fill(tiles->grid.begin() + ty * tilesX + tx0, tiles->grid.begin() + ty * tilesX + tx1 + 1,
                          uint8_t(1));
            }
        }
    }
    if (!any) {
        r.whole = false;  // nothing in front of the camera: an empty rect, no tiles
        return r;
    }
    // NDC to pixels, one pixel of slack for rasterisation rules, clamped to the view.
    r.x0 = std::max(0, int(std::floor(toPixel(lo[0], w))) - 1);
    r.y0 = std::max(0, int(std::floor(toPixel(lo[1], h))) - 1);
    r.x1 = std::min(w, int(std::ceil(toPixel(hi[0], w))) + 1);
    r.y1 = std::min(h, int(std::ceil(toPixel(hi[1], h))) + 1);
    if (r.x1 <= r.x0 || r.y1 <= r.y0) {
        r.x0 = r.x1 = r.y0 = r.y1 = 0;
        r.whole = false;
        return r;  // no tiles either: every bound was off screen
    }
    r.whole = r.x0 == 0 && r.y0 == 0 && r.x1 == w && r.y1 == h;
    if (tiles) {
        // Horizontal runs of marked tiles, clamped to the view.
        for (int ty = 0; ty < tilesY; ++ty) {
            const uint8_t* row = tiles->grid.data() + ty * tilesX;
            for (int tx = 0; tx < tilesX;) {
                if (!row[tx]) {
                    ++tx;
                    continue;
                }
                int end = tx;
                while (end < tilesX && row[end]) ++end;
                addRun(tiles, tx * kTileSize, ty * kTileSize, std::min(w, end * kTileSize),
                       std::min(h, (ty + 1) * kTileSize));
                tx = end;
            }
        }
    }
    return r;
}

HostClip HostClip::current() {
    HostClip c;
    c.on = glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE;
    if (c.on) glGetIntegerv(GL_SCISSOR_BOX, c.box);
    return c;
}

void HostClip::apply() const {
    if (!on) return;
    glEnable(GL_SCISSOR_TEST);
    glScissor(box[0], box[1], box[2], box[3]);
}

void scissorToView(const ScreenRect& rect, int border, const ViewInfo& view, const HostClip& clip) {
    if (rect.whole && !clip.on) {
        glDisable(GL_SCISSOR_TEST);
        return;
    }
    int x0 = view.x, y0 = view.y, x1 = view.x + view.width, y1 = view.y + view.height;
    if (!rect.whole) {
        x0 = std::max(x0, view.x + rect.x0 - border);
        y0 = std::max(y0, view.y + rect.y0 - border);
        x1 = std::min(x1, view.x + rect.x1 + border);
        y1 = std::min(y1, view.y + rect.y1 + border);
    }
    if (clip.on) {
        x0 = std::max(x0, clip.box[0]);
        y0 = std::max(y0, clip.box[1]);
        x1 = std::min(x1, clip.box[0] + clip.box[2]);
        y1 = std::min(y1, clip.box[1] + clip.box[3]);
    }
    glEnable(GL_SCISSOR_TEST);
    glScissor(x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0));
}

void scissorTo(const ScreenRect& rect, float scale, int border, int w, int h) {
    if (rect.whole) {
        glDisable(GL_SCISSOR_TEST);
        return;
    }
    const int x0 = std::max(0, int(std::floor(float(rect.x0) * scale)) - border);
    const int y0 = std::max(0, int(std::floor(float(rect.y0) * scale)) - border);
    const int x1 = std::min(w, int(std::ceil(float(rect.x1) * scale)) + border);
    const int y1 = std::min(h, int(std::ceil(float(rect.y1) * scale)) + border);
    glEnable(GL_SCISSOR_TEST);
    glScissor(x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0));
}

}  // namespace fx
