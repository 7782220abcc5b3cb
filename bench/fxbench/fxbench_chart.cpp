#include "fxbench_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fxbench_report.h"

namespace fxbench {

namespace {

const char* kPalette[] = {"#4c72b0", "#dd8452", "#55a868", "#c44e52", "#8172b3", "#937860", "#da8bc3", "#8c8c8c"};

std::string esc(const std::string& s) {
    std::string o;
    for (char c : s) {
        if (c == '<') o += "&lt;";
        else if (c == '>') o += "&gt;";
        else if (c == '&') o += "&amp;";
        else if (c == '"') o += "&quot;";
        else o += c;
    }
    return o;
}

std::string f(double v) { return num(v, 5); }

/// A "nice" tick step (1, 2 or 5 x 10^k) giving about `n` ticks over [0, range].
double niceStep(double range, int n) {
    if (!(range > 0.0)) return 1.0;
    const double raw = range / n;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    const double m = raw / p;
    return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * p;
}

std::string text(double x, double y, const std::string& s, const char* anchor = "start", int size = 12,
                 const char* extra = "") {
    return "<text x=\"" + f(x) + "\" y=\"" + f(y) + "\" font-size=\"" + std::to_string(size) +
           "\" text-anchor=\"" + anchor + "\" " + extra + ">" + esc(s) + "</text>\n";
}

std::string line(double x0, double y0, double x1, double y1, const char* stroke, double width = 1.0,
                 const char* extra = "") {
    return "<line x1=\"" + f(x0) + "\" y1=\"" + f(y0) + "\" x2=\"" + f(x1) + "\" y2=\"" + f(y1) + "\" stroke=\"" +
           stroke + "\" stroke-width=\"" + f(width) + "\" " + extra + "/>\n";
}

std::string rect(double x, double y, double w, double h, const char* fill) {
    return "<rect x=\"" + f(x) + "\" y=\"" + f(y) + "\" width=\"" + f(std::max(0.0, w)) + "\" height=\"" +
           f(std::max(0.0, h)) + "\" fill=\"" + fill + "\"/>\n";
}

std::string tickLabel(double v) {
    char b[32];
    if (std::fabs(v) >= 100 || v == std::floor(v)) std::snprintf(b, sizeof b, "%.0f", v);
    else std::snprintf(b, sizeof b, "%.3g", v);
    return b;
}

}  // namespace

std::string chartSvg(const Report& r) {
    const int n = int(r.modes.size());
    const double W = 1000, rowH = 30, top = 70;
    const double H = std::max(360.0, top + rowH * n + 70);
    std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + f(W) + "\" height=\"" + f(H) +
                    "\" viewBox=\"0 0 " + f(W) + " " + f(H) + "\" font-family=\"sans-serif\">\n";
    s += rect(0, 0, W, H, "#ffffff");
    char title[256];
    std::snprintf(title, sizeof title, "fxbench %s, %dx%d, %s (%s)", r.scenario.c_str(), r.width, r.height,
                  r.renderer.c_str(), r.timingMethod.c_str());
    s += text(W / 2, 24, title, "middle", 15, "font-weight=\"bold\"");

    // Left: bars.
    const double lx0 = 150, lx1 = 440;
    double maxMs = 0;
    for (const ModeSummary& m : r.modes) maxMs = std::max(maxMs, m.p95);
    const double step = niceStep(maxMs, 5);
    const double axisMax = std::max(step, std::ceil(maxMs / step) * step);
    auto bx = [&](double ms) { return lx0 + (lx1 - lx0) * ms / axisMax; };
    s += text((lx0 + lx1) / 2, 50, "median frame ms (darker: particle passes; whisker: p95)", "middle", 12);
    const double barBottom = top + rowH * n;
    for (double t = 0; t <= axisMax + 1e-9; t += step) {
        s += line(bx(t), top - 6, bx(t), barBottom, "#e0e0e0");
        s += text(bx(t), barBottom + 16, tickLabel(t), "middle", 11);
    }
    for (int i = 0; i < n; ++i) {
        const ModeSummary& m = r.modes[size_t(i)];
        const double y = top + rowH * i;
        s += text(lx0 - 8, y + rowH * 0.62, m.name, "end", 12);
        s += rect(lx0, y + 5, bx(m.p50) - lx0, rowH - 10, "#9db4d8");
        s += rect(lx0, y + 5, bx(std::min(m.particleMs, m.p50)) - lx0, rowH - 10, "#3b5b92");
        s += line(bx(m.p50), y + rowH / 2, bx(m.p95), y + rowH / 2, "#333333");
        s += line(bx(m.p95), y + 9, bx(m.p95), y + rowH - 9, "#333333");
        char label[64];
        std::snprintf(label, sizeof label, "%s ms, %.2fx hard", tickLabel(m.p50).c_str(), m.ratioVsHard);
        s += text(bx(m.p95) + 4, y + rowH * 0.62, label, "start", 10);
    }
    s += line(lx0, top - 6, lx0, barBottom, "#333333");
    s += text((lx0 + lx1) / 2, barBottom + 34, "ms", "middle", 11);

    // Right: error vs time scatter.
    const double sx0 = 580, sx1 = 880, sy0 = top - 6, sy1 = H - 60;
    double maxT = 0, maxE = 0;
    for (const ModeSummary& m : r.modes) {
        maxT = std::max(maxT, m.p50);
        maxE = std::max(maxE, m.rmse);
    }
    const double tStep = niceStep(maxT, 5), eStep = niceStep(std::max(maxE, 0.5), 5);
    const double tMax = std::max(tStep, std::ceil(maxT * 1.05 / tStep) * tStep);
    const double eMax = std::max(eStep, std::ceil(std::max(maxE, 0.5) * 1.1 / eStep) * eStep);
    auto px = [&](double t) { return sx0 + (sx1 - sx0) * t / tMax; };
    auto py = [&](double e) { return sy1 - (sy1 - sy0) * e / eMax; };
    s += text((sx0 + sx1) / 2, 50, "image error (RMSE, 8-bit) vs median frame ms", "middle", 12);
    for (double t = 0; t <= tMax + 1e-9; t += tStep) {
        s += line(px(t), sy0, px(t), sy1, "#eeeeee");
        s += text(px(t), sy1 + 16, tickLabel(t), "middle", 11);
    }
    for (double e = 0; e <= eMax + 1e-9; e += eStep) {
        s += line(sx0, py(e), sx1, py(e), "#eeeeee");
        s += text(sx0 - 6, py(e) + 4, tickLabel(e), "end", 11);
    }
    s += line(sx0, sy0, sx0, sy1, "#333333");
    s += line(sx0, sy1, sx1, sy1, "#333333");
    s += text((sx0 + sx1) / 2, sy1 + 34, "median frame ms", "middle", 11);
    s += text(sx0 - 40, (sy0 + sy1) / 2, "RMSE", "middle", 11,
              ("transform=\"rotate(-90 " + f(sx0 - 40) + " " + f((sy0 + sy1) / 2) + ")\"").c_str());
    // Points first, then labels placed greedily: right of the point, moved down (or up near the
    // axis) until they clear every label already placed.
    struct Box {
        double x0, y0, x1, y1;
    };
    std::vector<Box> placed;
    for (int i = 0; i < n; ++i) {
        const ModeSummary& m = r.modes[size_t(i)];
        s += "<circle cx=\"" + f(px(m.p50)) + "\" cy=\"" + f(py(m.rmse)) + "\" r=\"5\" fill=\"" + kPalette[i % 8] + "\"/>\n";
        placed.push_back({px(m.p50) - 5, py(m.rmse) - 5, px(m.p50) + 5, py(m.rmse) + 5});
    }
    for (int i = 0; i < n; ++i) {
        const ModeSummary& m = r.modes[size_t(i)];
        const double w = 6.2 * double(m.name.size()), x = px(m.p50) + 8;
        double y = py(m.rmse) - 7;  // baseline
        const double step = (y + 20 > sy1) ? -13.0 : 13.0;
        for (int tries = 0; tries < 12; ++tries) {
            bool hit = false;
            for (const Box& b : placed)
                hit |= x < b.x1 && x + w > b.x0 && y - 10 < b.y1 && y + 2 > b.y0;
            if (!hit) break;
            y += step;
        }
        placed.push_back({x, y - 10, x + w, y + 2});
        s += text(x, y, m.name, "start", 11, (std::string("fill=\"") + kPalette[i % 8] + "\"").c_str());
    }
    s += text(10, H - 12,
              "error vs the reference render of the same simulated frames (soft modes vs soft, spherical+quarter vs "
              "spherical; full-res techniques vs themselves = 0)",
              "start", 10, "fill=\"#555555\"");
    s += "</svg>\n";
    return s;
}

std::string sweepChartSvg(const std::string& title, const std::string& xLabel, const std::vector<SweepSeries>& series,
                          bool logScale) {
    const double W = 760, H = 440, x0 = 80, x1 = 600, y0 = 50, y1 = 380;
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = 0;
    for (const SweepSeries& sr : series)
        for (size_t i = 0; i < sr.x.size(); ++i) {
            xmin = std::min(xmin, sr.x[i]);
            xmax = std::max(xmax, sr.x[i]);
            ymin = std::min(ymin, sr.y[i]);
            ymax = std::max(ymax, sr.y[i]);
        }
    if (xmin > xmax) xmin = 0, xmax = 1, ymin = 0;
    // Log-log: a cost proportional to the work is a line of slope 1.
    const bool logX = logScale && xmin > 0, logY = logScale && ymin > 0;
    const double lx0 = logX ? std::floor(std::log10(xmin) + 1e-9) : 0.0;
    const double lx1 = logX ? std::max(lx0 + 1, std::ceil(std::log10(xmax) - 1e-9)) : xmax * 1.05;
    auto px = [&](double v) {
        const double t = logX ? (std::log10(v) - lx0) / std::max(1e-9, lx1 - lx0) : v / std::max(1e-9, lx1);
        return x0 + (x1 - x0) * t;
    };
    const double yStep = niceStep(ymax, 5);
    const double yMax = std::max(yStep, std::ceil(ymax * 1.05 / yStep) * yStep);
    const double ly0 = logY ? std::floor(std::log10(ymin) + 1e-9) : 0.0;
    const double ly1 = logY ? std::max(ly0 + 1, std::ceil(std::log10(ymax) - 1e-9)) : 0.0;
    auto py = [&](double v) {
        const double t = logY ? (std::log10(v) - ly0) / (ly1 - ly0) : v / yMax;
        return y1 - (y1 - y0) * t;
    };
    std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + f(W) + "\" height=\"" + f(H) +
                    "\" viewBox=\"0 0 " + f(W) + " " + f(H) + "\" font-family=\"sans-serif\">\n";
    s += rect(0, 0, W, H, "#ffffff");
    s += text(W / 2, 26, title, "middle", 15, "font-weight=\"bold\"");
    if (logY) {
        for (double e = ly0; e <= ly1 + 1e-9; e += 1.0) {
            const double v = std::pow(10.0, e);
            s += line(x0, py(v), x1, py(v), "#eeeeee");
            s += text(x0 - 6, py(v) + 4, tickLabel(v), "end", 11);
        }
    } else {
        for (double v = 0; v <= yMax + 1e-9; v += yStep) {
            s += line(x0, py(v), x1, py(v), "#eeeeee");
            s += text(x0 - 6, py(v) + 4, tickLabel(v), "end", 11);
        }
    }
    if (logX) {
        for (double e = lx0; e <= lx1 + 1e-9; e += 1.0) {
            const double v = std::pow(10.0, e);
            s += line(px(v), y0, px(v), y1, "#eeeeee");
            s += text(px(v), y1 + 16, tickLabel(v), "middle", 11);
        }
    } else {
        const double xs = niceStep(lx1, 5);
        for (double v = 0; v <= lx1 + 1e-9; v += xs) {
            s += line(px(v), y0, px(v), y1, "#eeeeee");
            s += text(px(v), y1 + 16, tickLabel(v), "middle", 11);
        }
    }
    s += line(x0, y0, x0, y1, "#333333");
    s += line(x0, y1, x1, y1, "#333333");
    s += text((x0 + x1) / 2, y1 + 36, xLabel + (logX ? " (log scale)" : ""), "middle", 12);
    s += text(24, (y0 + y1) / 2, std::string("median frame ms") + (logY ? " (log scale)" : ""), "middle", 12,
              ("transform=\"rotate(-90 24 " + f((y0 + y1) / 2) + ")\"").c_str());
    for (size_t k = 0; k < series.size(); ++k) {
        const SweepSeries& sr = series[k];
        const char* c = kPalette[k % 8];
        std::string pts;
        for (size_t i = 0; i < sr.x.size(); ++i) pts += f(px(sr.x[i])) + "," + f(py(sr.y[i])) + " ";
        s += "<polyline fill=\"none\" stroke=\"" + std::string(c) + "\" stroke-width=\"2\" points=\"" + pts + "\"/>\n";
        for (size_t i = 0; i < sr.x.size(); ++i)
            s += "<circle cx=\"" + f(px(sr.x[i])) + "\" cy=\"" + f(py(sr.y[i])) + "\" r=\"3.5\" fill=\"" + c + "\"/>\n";
        s += rect(615, y0 + 20 * double(k), 14, 10, c);
        s += text(635, y0 + 20 * double(k) + 10, sr.mode, "start", 12);
    }
    s += "</svg>\n";
    return s;
}

}  // namespace fxbench
