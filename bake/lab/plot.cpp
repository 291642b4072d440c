#include "plot.hpp"

#include "world/images/image_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wshadow"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace onelight::lab {

namespace {

constexpr int kWidth = 960, kHeight = 600;
constexpr int kLeft = 90, kRight = 220, kTop = 60, kBottom = 70;  // margins around the axes
using Rgb = std::array<uint8_t, 3>;

struct Canvas {
    std::vector<uint8_t> pixels = std::vector<uint8_t>(size_t(kWidth) * kHeight * 4, 255);  // RGBA
    void set(int x, int y, Rgb c) {
        if (x < 0 || y < 0 || x >= kWidth || y >= kHeight) return;
        uint8_t* p = &pixels[(size_t(y) * kWidth + x) * 4];
        p[0] = c[0], p[1] = c[1], p[2] = c[2];
    }
    void rect(int x0, int y0, int x1, int y1, Rgb c) {
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) set(x, y, c);
    }
    void disc(double cx, double cy, double r, Rgb c) {
        for (int y = int(cy - r - 1); y <= int(cy + r + 1); ++y)
            for (int x = int(cx - r - 1); x <= int(cx + r + 1); ++x)
                if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) set(x, y, c);
    }
    void line(double x0, double y0, double x1, double y1, Rgb c, double width = 1.5) {
        int steps = int(std::max(std::abs(x1 - x0), std::abs(y1 - y0))) + 1;
        for (int i = 0; i <= steps; ++i) {
            double t = double(i) / steps;
            disc(x0 + (x1 - x0) * t, y0 + (y1 - y0) * t, std::max(width * 0.5, 0.75), c);
        }
    }
    // Text at scale 2 (stb_easy_font glyphs are about 6 x 7 units); returns the width in pixels.
    int text(double x, double y, const std::string& s, Rgb c, int scale = 2) {
        std::vector<char> buffer(s.size() * 1024 + 64);  // up to 16 quads of 64 bytes a glyph
        std::string copy = s;
        int quads =
            stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size()));
        const float* v = reinterpret_cast<const float*>(buffer.data());
        for (int q = 0; q < quads; ++q) {
            const float* a = v + q * 16;  // 4 vertices of (x, y, z, rgba)
            const float* b = a + 8;       // the opposite corner
            rect(int(x + double(a[0]) * scale), int(y + double(a[1]) * scale),
                 int(x + double(b[0]) * scale), int(y + double(b[1]) * scale), c);
        }
        return stb_easy_font_width(copy.data()) * scale;
    }
};

struct Axis {
    bool log;
    double lo, hi;  // in axis units (log10 when log)
    double map(double v) const { return ((log ? std::log10(v) : v) - lo) / (hi - lo); }
};

bool usable(double v, bool log) {
    return std::isfinite(v) && (!log || v > 0.0);
}

Axis makeAxis(const std::vector<double>& values, bool log) {
    double lo = 1e300, hi = -1e300;
    for (double v : values) {
        double a = log ? std::log10(v) : v;
        lo = std::min(lo, a), hi = std::max(hi, a);
    }
    if (lo > hi) lo = 0, hi = 1;
    if (log) {
        lo = std::floor(lo), hi = std::ceil(hi);
        if (hi <= lo) hi = lo + 1;
    } else {
        double pad = (hi - lo) * 0.08 + (hi == lo ? 1.0 : 0.0);
        lo = std::min(0.0, lo - pad), hi = hi + pad;
    }
    return {log, lo, hi};
}

// Tick values in data units.
std::vector<double> ticks(const Axis& a) {
    std::vector<double> t;
    if (a.log) {
        for (int e = int(a.lo); e <= int(a.hi); ++e) t.push_back(std::pow(10.0, e));
        return t;
    }
    double raw = (a.hi - a.lo) / 6.0, mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = raw / mag < 2 ? 2 * mag : raw / mag < 5 ? 5 * mag : 10 * mag;
    for (double v = std::ceil(a.lo / step) * step; v <= a.hi + 1e-12; v += step) t.push_back(v);
    return t;
}

std::string tickLabel(double v, bool log) {
    char buf[32];
    if (log)
        std::snprintf(buf, sizeof buf, "1e%d", int(std::lround(std::log10(v))));
    else
        std::snprintf(buf, sizeof buf, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
    return buf;
}

}  // namespace

std::array<uint8_t, 3> seriesColor(int i) {
    static const Rgb palette[] = {{31, 119, 180},  {255, 127, 14}, {44, 160, 44},   {214, 39, 40},
                                  {148, 103, 189}, {140, 86, 75},  {227, 119, 194}, {127, 127, 127},
                                  {188, 189, 34},  {23, 190, 207}, {0, 0, 0},       {128, 0, 0},
                                  {0, 90, 90},     {230, 180, 0}};
    return palette[i % 14];
}

void writePlotPng(const std::string& path, const Plot& plot) {
    std::vector<double> xs, ys;
    for (const PlotSeries& s : plot.series)
        for (auto [x, y] : s.points)
            if (usable(x, plot.logX) && usable(y, plot.logY)) xs.push_back(x), ys.push_back(y);
    Axis ax = makeAxis(xs, plot.logX), ay = makeAxis(ys, plot.logY);
    Canvas c;
    const Rgb black{0, 0, 0}, grey{220, 220, 220};
    int x0 = kLeft, x1 = kWidth - kRight, y0 = kTop, y1 = kHeight - kBottom;
    auto px = [&](double x) { return x0 + ax.map(x) * (x1 - x0); };
    auto py = [&](double y) { return y1 - ay.map(y) * (y1 - y0); };

    for (double t : ticks(ax)) {
        c.line(px(t), y0, px(t), y1, grey, 1.0);
        std::string l = tickLabel(t, ax.log);
        c.text(px(t) - 6.0 * l.size() * 0.5 * 2 / 2, y1 + 8, l, black);
    }
    for (double t : ticks(ay)) {
        c.line(x0, py(t), x1, py(t), grey, 1.0);
        std::string l = tickLabel(t, ay.log);
        c.text(x0 - 12 - 10.0 * l.size(), py(t) - 7, l, black);
    }
    c.line(x0, y1, x1, y1, black), c.line(x0, y0, x0, y1, black);
    c.line(x1, y0, x1, y1, black), c.line(x0, y0, x1, y0, black);
    c.text(8, 4, plot.title, black);
    c.text((x0 + x1) / 2.0 - 5.0 * plot.xLabel.size(), kHeight - 30, plot.xLabel, black);
    c.text(8, y0 - 24, plot.yLabel, black);

    int legendY = y0;
    for (const PlotSeries& s : plot.series) {
        std::vector<std::pair<double, double>> pts;
        for (auto [x, y] : s.points)
            if (usable(x, plot.logX) && usable(y, plot.logY)) pts.emplace_back(px(x), py(y));
        for (size_t i = 0; i + 1 < pts.size() && s.line; ++i)
            c.line(pts[i].first, pts[i].second, pts[i + 1].first, pts[i + 1].second, s.color, 2.5);
        for (auto [x, y] : pts) {
            c.disc(x, y, s.line ? 3.0 : 6.0, s.color);
            if (s.labelPoints) c.text(x + 9, y - 7, s.label, s.color);
        }
        if (!s.inLegend) continue;
        c.rect(x1 + 15, legendY + 2, x1 + 29, legendY + 16, s.color);
        c.text(x1 + 35, legendY + 2, s.label, black);
        legendY += 24;
    }
    world::writePngFile(path, kWidth, kHeight, c.pixels);
}

}  // namespace onelight::lab
