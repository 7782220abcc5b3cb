#include "TrimmedShapes.h"

#include <algorithm>
#include <cmath>

namespace fx {
namespace {

constexpr int kCellsX = 2, kCellsY = 2;
// Bilinear reach of a texel around its centre is 1 texel (open); a 1/64-texel pad keeps fragment
// centres that rasterisation and interpolation round differently inside.
constexpr double kReach = 1.0 + 1.0 / 64.0;

using Point = glm::dvec2;

double cross(const Point& o, const Point& a, const Point& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain; counter-clockwise, no collinear points.
std::vector<Point> convexHull(std::vector<Point> p) {
    std::sort(p.begin(), p.end(), [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (p.size() < 3) return p;
    std::vector<Point> h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0.0) --k;
        h[k++] = p[i - 1];
    }
    h.resize(k - 1);
    return h;
}

bool insideSquare(const Point& p) { return std::fabs(p.x) <= 1.0 + 1e-9 && std::fabs(p.y) <= 1.0 + 1e-9; }

// Fewer vertices, still containing the polygon and inside the square: repeatedly drop the edge
// whose removal (its two neighbours extended to meet) adds the least area.
std::vector<Point> reduce(std::vector<Point> poly, size_t maxVertices) {
    while (poly.size() > maxVertices) {
        const size_t n = poly.size();
        double bestArea = 1e300;
        size_t best = n;
        Point bestX;
        for (size_t i = 0; i < n; ++i) {
            const Point& a = poly[(i + n - 1) % n];
            const Point& b = poly[i];
            const Point& c = poly[(i + 1) % n];
            const Point& d = poly[(i + 2) % n];
            // Lines a->b and d->c meet beyond the edge b-c only if they turn towards each other.
            const Point r = b - a, s = c - d;
            const double den = r.x * s.y - r.y * s.x;
            if (std::fabs(den) < 1e-15) continue;
            const double t = ((d.x - a.x) * s.y - (d.y - a.y) * s.x) / den;
            if (t < 1.0) continue;  // would cut into the polygon
            const Point x = a + t * r;
            if (!insideSquare(x)) continue;
            const double area = 0.5 * std::fabs(cross(b, x, c));
            if (area < bestArea) {
                bestArea = area;
                best = i;
                bestX = x;
            }
        }
        if (best == n) return {};  // nothing removable: the caller falls back to the quad
        const size_t next = (best + 1) % n;
        poly[best] = bestX;
        poly.erase(poly.begin() + long(next));
    }
    return poly;
}

double area(const std::vector<Point>& poly) {
    double a = 0.0;
    for (size_t i = 0; i < poly.size(); ++i) a += cross(Point(0.0), poly[i], poly[(i + 1) % poly.size()]);
    return 0.5 * std::fabs(a);
}

// The part of convex polygon `poly` (counter-clockwise) on the side n.x <= 1 of a line
// (Sutherland-Hodgman against one half-plane).
std::vector<Point> clipHalfPlane(const std::vector<Point>& poly, const Point& n) {
    std::vector<Point> out;
    const size_t count = poly.size();
    for (size_t i = 0; i < count; ++i) {
        const Point& a = poly[i];
        const Point& b = poly[(i + 1) % count];
        const double da = glm::dot(n, a) - 1.0, db = glm::dot(n, b) - 1.0;
        if (da <= 0.0) out.push_back(a);
        if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

// Convex polygon `poly` clipped to a regular 64-gon circumscribed about the unit disc: it holds
// poly's part of the disc, and is at most 1/cos(pi/64) - 1 = 0.12 % outside it.
std::vector<Point> clipToDisc(std::vector<Point> poly) {
    constexpr int kSides = 64;
    for (int i = 0; i < kSides && poly.size() >= 3; ++i) {
        const double a = 2.0 * 3.14159265358979323846 * double(i) / kSides;
        poly = clipHalfPlane(poly, Point(std::cos(a), std::sin(a)));
    }
    return poly;
}

// The regular octagon circumscribed about the unit disc (inside the square): the disc polygon of
// a frame whose clipped support cannot be reduced to kMaxVertices.
std::vector<Point> discOctagon() {
    std::vector<Point> p;
    const double t = std::tan(3.14159265358979323846 / 8.0);
    for (const Point& v : {Point(1, -t), Point(1, t), Point(t, 1), Point(-t, 1), Point(-1, t), Point(-1, -t),
                           Point(-t, -1), Point(t, -1)}) {
        p.push_back(v);
    }
    return p;
}

// Stores `poly` (counter-clockwise, at most kMaxVertices) padded by repeating its last vertex,
// rounded to float and clamped to the square.
int store(const std::vector<Point>& poly, std::array<glm::vec2, TrimmedShapes::kMaxVertices>* out) {
    for (size_t i = 0; i < out->size(); ++i) {
        const Point p = poly.empty() ? Point(0.0) : poly[std::min(i, poly.size() - 1)];
        (*out)[i] = glm::vec2(float(glm::clamp(p.x, -1.0, 1.0)), float(glm::clamp(p.y, -1.0, 1.0)));
    }
    return int(poly.size());
}

}  // namespace

bool TrimmedShapes::compute(const uint8_t* rgba, int w, int h, int maxLevel) {
    levels_.clear();
    buckets_ = 0;
    if (!rgba || w < 2 || h < 2 || (w % 2) || (h % 2)) return false;
    cellW_ = w / kCellsX;
    cellH_ = h / kCellsY;
    maxLevel = std::max(0, maxLevel);

    // Non-zero masks of every level ("any texel below is non-zero": conservative for any box
    // filter, odd sizes included).
    Level base;
    base.w = w;
    base.h = h;
    base.nonZero.resize(size_t(w) * size_t(h));
    for (size_t i = 0; i < base.nonZero.size(); ++i) base.nonZero[i] = rgba[i * 4 + 3] != 0;
    levels_.push_back(std::move(base));
    for (int k = 1; k <= maxLevel; ++k) {
        const Level& up = levels_.back();
        Level l;
        l.w = std::max(1, up.w / 2);
        l.h = std::max(1, up.h / 2);
        l.nonZero.assign(size_t(l.w) * size_t(l.h), 0);
        for (int y = 0; y < up.h; ++y) {
            for (int x = 0; x < up.w; ++x) {
                if (!up.nonZero[size_t(y) * size_t(up.w) + size_t(x)]) continue;
                const int lx = std::min(x / 2, l.w - 1), ly = std::min(y / 2, l.h - 1);
                l.nonZero[size_t(ly) * size_t(l.w) + size_t(lx)] = 1;
            }
        }
        levels_.push_back(std::move(l));
    }

    buckets_ = std::min(kMaxBuckets, maxLevel + 1);
    for (int f = 0; f < kFrames; ++f) {
        const int cx = f % kCellsX, cy = f / kCellsX;
        const double u0 = double(cx) / kCellsX, u1 = double(cx + 1) / kCellsX;
        const double v0 = double(cy) / kCellsY, v1 = double(cy + 1) / kCellsY;
        for (int b = 0; b < buckets_; ++b) {
            std::vector<Point> pts;
            const int topLevel = std::min(b, maxLevel);
            for (int k = 0; k <= topLevel; ++k) {
                const Level& l = levels_[size_t(k)];
                for (int y = 0; y < l.h; ++y) {
                    // Per row only the outermost texels whose reach meets the cell matter.
                    const double vlo = std::max((y + 0.5 - kReach) / l.h, v0);
                    const double vhi = std::min((y + 0.5 + kReach) / l.h, v1);
                    if (vlo >= vhi) continue;
                    int first = -1, last = -1;
                    for (int x = 0; x < l.w; ++x) {
                        if (!l.nonZero[size_t(y) * size_t(l.w) + size_t(x)]) continue;
                        if ((x + 0.5 + kReach) / l.w <= u0 || (x + 0.5 - kReach) / l.w >= u1) continue;
                        if (first < 0) first = x;
                        last = x;
                    }
                    if (first < 0) continue;
                    const double ulo = std::max((first + 0.5 - kReach) / l.w, u0);
                    const double uhi = std::min((last + 0.5 + kReach) / l.w, u1);
                    // Texture space of the cell: x = 4u - 2cx - 1, y = 1 - 4v + 2cy (+y up).
                    for (double u : {ulo, uhi}) {
                        for (double v : {vlo, vhi}) {
                            pts.emplace_back(kCellsX * 2.0 * u - 2.0 * cx - 1.0, 1.0 - kCellsY * 2.0 * v + 2.0 * cy);
                        }
                    }
                }
            }
            const std::vector<Point> hull = convexHull(pts);
            std::vector<Point> poly = hull.size() >= 3 ? reduce(hull, kMaxVertices) : std::vector<Point>{};
            if (hull.size() >= 3 && poly.size() < 3) {
                poly = {Point(-1, -1), Point(1, -1), Point(1, 1), Point(-1, 1)};
            }
            const size_t fi = size_t(f), bi = size_t(b);
            square_.counts[fi][bi] = store(poly, &square_.polygons[fi][bi]);
            // Spheres: the hull's part of the unit disc. Clipping keeps it convex and
            // counter-clockwise; reduce() then only grows it, inside the square.
            std::vector<Point> clipped = hull.size() >= 3 ? clipToDisc(hull) : std::vector<Point>{};
            std::vector<Point> round = clipped.size() >= 3 ? reduce(clipped, kMaxVertices) : std::vector<Point>{};
            if (clipped.size() >= 3 && round.size() < 3) round = discOctagon();
            // Reducing the clipped polygon can give away more than the square's polygon, which
            // holds the clipped support too: keep the smaller.
            if (round.size() >= 3 && poly.size() >= 3 && area(poly) < area(round)) round = poly;
            disc_.counts[fi][bi] = store(round, &disc_.polygons[fi][bi]);
        }
    }
    return true;
}

const std::array<glm::vec2, TrimmedShapes::kMaxVertices>& TrimmedShapes::polygon(int frame, int bucket, Clip clip) const {
    return table(clip).polygons[size_t(glm::clamp(frame, 0, kFrames - 1))][size_t(glm::clamp(bucket, 0, std::max(0, buckets_ - 1)))];
}

int TrimmedShapes::vertexCount(int frame, int bucket, Clip clip) const {
    return table(clip).counts[size_t(glm::clamp(frame, 0, kFrames - 1))][size_t(glm::clamp(bucket, 0, std::max(0, buckets_ - 1)))];
}

float TrimmedShapes::reach(int frame, int bucket, Clip clip) const {
    const auto& p = polygon(frame, bucket, clip);
    const int n = vertexCount(frame, bucket, clip);
    if (n < 3) return std::sqrt(2.0f);
    double farthest = 0.0;
    for (int i = 0; i < n; ++i) farthest = std::max(farthest, glm::length(glm::dvec2(p[size_t(i)])));
    // Rounded up to float, so a bound made from it never falls short.
    const float r = float(farthest);
    return double(r) < farthest ? std::nextafter(r, 2.0f) : r;
}

float TrimmedShapes::inradius(int frame, int bucket, Clip clip) const {
    const auto& p = polygon(frame, bucket, clip);
    const int n = vertexCount(frame, bucket, clip);
    if (n < 3) return 0.0f;
    double least = 1e30;
    for (int i = 0; i < n; ++i) {
        const glm::dvec2 a(p[size_t(i)]), b(p[size_t((i + 1) % n)]);
        const double len = glm::length(b - a);
        if (len <= 0.0) continue;
        // Signed distance of (0, 0) to the edge's line, positive on the inner (left) side.
        least = std::min(least, (a.x * b.y - a.y * b.x) / len);
    }
    // Rounded down to float, so the shader's growth never falls short.
    return least > 0.0 && least < 1e30 ? std::nextafter(float(least), 0.0f) : 0.0f;
}

float TrimmedShapes::areaShare(int frame, int bucket, Clip clip) const {
    const auto& p = polygon(frame, bucket, clip);
    const std::vector<Point> points(p.begin(), p.begin() + vertexCount(frame, bucket, clip));
    return float(area(points) / 4.0);
}

std::vector<glm::vec4> TrimmedShapes::packed(Clip clip) const {
    std::vector<glm::vec4> out;
    out.reserve(size_t(kFrames * buckets_ * kMaxVertices / 2));
    for (int f = 0; f < kFrames; ++f) {
        for (int b = 0; b < buckets_; ++b) {
            const auto& p = table(clip).polygons[size_t(f)][size_t(b)];
            for (int i = 0; i < kMaxVertices; i += 2) out.emplace_back(p[size_t(i)], p[size_t(i + 1)]);
        }
    }
    return out;
}

std::vector<glm::vec4> TrimmedShapes::packedInfo(Clip clip) const {
    std::vector<float> flat;
    for (int f = 0; f < kFrames; ++f) {
        for (int b = 0; b < buckets_; ++b) {
            flat.push_back(inradius(f, b, clip));
            flat.push_back(areaShare(f, b, clip));
        }
    }
    flat.resize((flat.size() + 3) / 4 * 4, 0.0f);
    std::vector<glm::vec4> out;
    for (size_t i = 0; i < flat.size(); i += 4) out.emplace_back(flat[i], flat[i + 1], flat[i + 2], flat[i + 3]);
    return out;
}

bool TrimmedShapes::sampleSupport(int frame, int level, glm::vec2 p) const {
    if (levels_.empty()) return false;
    const Level& l = levels_[size_t(glm::clamp(level, 0, int(levels_.size()) - 1))];
    const int cx = frame % kCellsX, cy = frame / kCellsX;
    // atlasUV(): clamp to the square, then into the cell.
    const double x = glm::clamp(double(p.x), -1.0, 1.0), y = glm::clamp(double(p.y), -1.0, 1.0);
    const double u = (cx + 0.5 + 0.5 * x) / kCellsX, v = (cy + 0.5 - 0.5 * y) / kCellsY;
    const double tx = u * l.w - 0.5, ty = v * l.h - 0.5;
    const int x0 = int(std::floor(tx)), y0 = int(std::floor(ty));
    for (int j = y0; j <= y0 + 1; ++j) {
        for (int i = x0; i <= x0 + 1; ++i) {
            // Weight of texel (i, j) is (1 - |tx - i|)(1 - |ty - j|): zero exactly on the far side.
            if (std::fabs(tx - i) >= 1.0 || std::fabs(ty - j) >= 1.0) continue;
            const int ci = glm::clamp(i, 0, l.w - 1), cj = glm::clamp(j, 0, l.h - 1);  // clamp to edge
            if (l.nonZero[size_t(cj) * size_t(l.w) + size_t(ci)]) return true;
        }
    }
    return false;
}

bool TrimmedShapes::contains(const std::array<glm::vec2, kMaxVertices>& polygon, int count, glm::vec2 p) {
    if (count < 3) return false;
    for (int i = 0; i < count; ++i) {
        const glm::vec2 a = polygon[size_t(i)], b = polygon[size_t((i + 1) % count)];
        const double c = (double(b.x) - a.x) * (double(p.y) - a.y) - (double(b.y) - a.y) * (double(p.x) - a.x);
        if (c < -1e-7) return false;
    }
    return true;
}

}  // namespace fx
