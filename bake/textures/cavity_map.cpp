// Height from normals by an exact Poisson solve (FFT along a repeating axis, DCT-II along a
// clamped one), cavity by horizon scans (cavity_map.hpp).
#include "bake/textures/cavity_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <string>

#include "bake/parallel_for.hpp"

namespace onelight::bake {

namespace {

constexpr uint32_t kMaxAzimuths = 1024;
constexpr float kMaxRadius = 4096.0f;

// ---------------------------------------------------------------------------------------------
// Complex numbers, written out: std::complex's operator* takes the Annex G path (NaN and
// infinity recovery) in ISO mode, several times slower than the four products.

struct Complex {
    double re = 0.0, im = 0.0;
};

Complex operator+(Complex a, Complex b) {
    return {a.re + b.re, a.im + b.im};
}
Complex operator-(Complex a, Complex b) {
    return {a.re - b.re, a.im - b.im};
}
Complex operator*(Complex a, Complex b) {
    return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}
Complex operator*(Complex a, double s) {
    return {a.re * s, a.im * s};
}
Complex conjugate(Complex a) {
    return {a.re, -a.im};
}
Complex unitPhase(double radians) {
    return {std::cos(radians), std::sin(radians)};
}

bool isPowerOfTwo(size_t n) {
    return n != 0 && (n & (n - 1)) == 0;
}

size_t powerOfTwoAtLeast(size_t n) {
    size_t p = 1;
    while (p < n) p <<= 1;
    return p;
}

// The forward DFT X_k = sum_j x_j e^(-2 pi i jk / n) of a power-of-two length, in place:
// iterative radix-2, decimation in time.
class Radix2Fft {
public:
    explicit Radix2Fft(size_t n) : n_(n), roots_(n / 2), reversed_(n) {
        for (size_t k = 0; k < n / 2; ++k)
            roots_[k] = unitPhase(-2.0 * std::numbers::pi * double(k) / double(n));
        size_t bits = 0;
        while ((size_t(1) << bits) < n) ++bits;
        for (size_t i = 0; i < n; ++i) {
            size_t r = 0;
            for (size_t b = 0; b < bits; ++b) r |= ((i >> b) & 1u) << (bits - 1 - b);
            reversed_[i] = r;
        }
    }

    size_t size() const { return n_; }

    void forward(Complex* a) const {
        for (size_t i = 0; i < n_; ++i)
            if (i < reversed_[i]) std::swap(a[i], a[reversed_[i]]);
        for (size_t half = 1; half < n_; half <<= 1) {
            const size_t stride = n_ / (2 * half);
            for (size_t start = 0; start < n_; start += 2 * half)
                for (size_t j = 0; j < half; ++j) {
                    const Complex u = a[start + j];
                    const Complex v = a[start + j + half] * roots_[j * stride];
                    a[start + j] = u + v;
                    a[start + j + half] = u - v;
                }
        }
    }

private:
    size_t n_;
    std::vector<Complex> roots_;
    std::vector<size_t> reversed_;
};

// The forward and inverse DFT of any length n >= 1. Other than powers of two: Bluestein's chirp
// z-transform (Bluestein 1970, "A Linear Filtering Approach to the Computation of Discrete
// Fourier Transform"): jk = (j^2 + k^2 - (k - j)^2) / 2 turns the DFT into a convolution,
//   X_k = c_k sum_j (x_j c_j) conj(c_(k-j)),  c_k = e^(-i pi k^2 / n),
// done as a cyclic convolution of a power-of-two length m >= 2n - 1.
class Dft {
public:
    explicit Dft(size_t n)
        : n_(n), fft_(isPowerOfTwo(n) ? n : powerOfTwoAtLeast(2 * n - 1)), chirp_(), kernel_() {
        if (isPowerOfTwo(n)) return;
        const size_t m = fft_.size();
        chirp_.resize(n);
        for (size_t k = 0; k < n; ++k) {
            const size_t k2 = (k * k) % (2 * n);  // e^(-i pi k^2 / n) has period 2n in k^2
            chirp_[k] = unitPhase(-std::numbers::pi * double(k2) / double(n));
        }
        kernel_.assign(m, Complex{});
        kernel_[0] = conjugate(chirp_[0]);
        for (size_t k = 1; k < n; ++k) kernel_[k] = kernel_[m - k] = conjugate(chirp_[k]);
        fft_.forward(kernel_.data());
    }

    size_t size() const { return n_; }

    // Complex values `work` must hold.
    size_t workSize() const { return isPowerOfTwo(n_) ? 0 : fft_.size(); }

    void forward(Complex* a, Complex* work) const {
        if (isPowerOfTwo(n_)) return fft_.forward(a);
        const size_t m = fft_.size();
        for (size_t j = 0; j < n_; ++j) work[j] = a[j] * chirp_[j];
        std::fill(work + n_, work + m, Complex{});
        fft_.forward(work);
        for (size_t k = 0; k < m; ++k) work[k] = conjugate(work[k] * kernel_[k]);
        fft_.forward(work);  // the inverse, by conjugation: ifft(x) = conj(fft(conj(x))) / m
        const double scale = 1.0 / double(m);
        for (size_t k = 0; k < n_; ++k) a[k] = conjugate(work[k]) * chirp_[k] * scale;
    }

    // x_j = (1/n) sum_k X_k e^(2 pi i jk / n).
    void inverse(Complex* a, Complex* work) const {
        for (size_t k = 0; k < n_; ++k) a[k] = conjugate(a[k]);
        forward(a, work);
        const double scale = 1.0 / double(n_);
        for (size_t k = 0; k < n_; ++k) a[k] = conjugate(a[k]) * scale;
    }

private:
    size_t n_;
    Radix2Fft fft_;
    std::vector<Complex> chirp_;   // c_k, k < n (Bluestein only)
    std::vector<Complex> kernel_;  // the DFT of conj(c) laid out cyclically (Bluestein only)
};

// The transform of one axis that diagonalises the Laplacian of its wrap mode, with the
// eigenvalues, on lines of n complex values (a complex line is two real lines at once).
//   repeat: the DFT; lambda_k = 2 cos(2 pi k / n) - 2.
//   clamp:  the DCT-II C_k = sum_j x_j cos(pi k (j + 1/2) / n), by the DFT Y of the mirrored
//           line y (y_j = y_(2n-1-j) = x_j): Y_k = 2 e^(i pi k / 2n) C_k; and back, Y_n = 0,
//           Y_(2n-k) = 2 e^(-i pi k / 2n) C_k. lambda_k = 2 cos(pi k / n) - 2.
class AxisTransform {
public:
    AxisTransform(size_t n, CavityWrap wrap)
        : n_(n), clamp_(wrap == CavityWrap::kClamp), dft_(clamp_ ? 2 * n : n), eigen_(n) {
        for (size_t k = 0; k < n; ++k) {
            const double period = clamp_ ? 2.0 * double(n) : double(n);
            eigen_[k] =
                k == 0 ? 0.0 : 2.0 * std::cos(2.0 * std::numbers::pi * double(k) / period) - 2.0;
        }
        if (clamp_) {
            halfShift_.resize(n);
            for (size_t k = 0; k < n; ++k)
                halfShift_[k] = unitPhase(-std::numbers::pi * double(k) / (2.0 * double(n)));
        }
    }

    double eigenvalue(size_t k) const { return eigen_[k]; }
    size_t workSize() const { return dft_.size() + dft_.workSize(); }

    void forward(Complex* line, Complex* work) const {
        if (!clamp_) return dft_.forward(line, work);
        Complex* mirrored = work;
        for (size_t j = 0; j < n_; ++j) mirrored[j] = mirrored[2 * n_ - 1 - j] = line[j];
        dft_.forward(mirrored, work + 2 * n_);
        for (size_t k = 0; k < n_; ++k) line[k] = mirrored[k] * halfShift_[k] * 0.5;
    }

    void inverse(Complex* line, Complex* work) const {
        if (!clamp_) return dft_.inverse(line, work);
        Complex* spectrum = work;
        spectrum[0] = line[0] * 2.0;
        spectrum[n_] = Complex{};
        for (size_t k = 1; k < n_; ++k) {
            spectrum[k] = line[k] * conjugate(halfShift_[k]) * 2.0;
            spectrum[2 * n_ - k] = line[k] * halfShift_[k] * 2.0;
        }
        dft_.inverse(spectrum, work + 2 * n_);
        for (size_t j = 0; j < n_; ++j) line[j] = spectrum[j];
    }

private:
    size_t n_;
    bool clamp_;
    Dft dft_;
    std::vector<double> eigen_;
    std::vector<Complex> halfShift_;  // e^(-i pi k / 2n), clamp only
};

// div(s) at every texel: the fitted height differences of the edges leaving it minus those of
// the edges reaching it (the normal equations of E(h) read laplacian(h) = div). Edges per axis:
// between neighbours, plus last to first when the axis repeats.
std::vector<Complex> slopeDivergence(const std::vector<glm::dvec2>& slopePerTexel, size_t w,
                                     size_t h, CavityWrapModes wrap) {
    std::vector<Complex> div(w * h);
    // Along a row: edge (x, x+1) carries d = (sx(x) + sx(x+1)) / 2; div(x) += d(x) - d(x-1).
    const size_t rowEdges = wrap.u == CavityWrap::kRepeat ? w : w - 1;
    const size_t colEdges = wrap.v == CavityWrap::kRepeat ? h : h - 1;
    for (size_t y = 0; y < h; ++y)
        for (size_t e = 0; e < rowEdges; ++e) {
            const size_t a = y * w + e, b = y * w + (e + 1) % w;
            const double d = 0.5 * (slopePerTexel[a].x + slopePerTexel[b].x);
            div[a].re += d;
            div[b].re -= d;
        }
    for (size_t e = 0; e < colEdges; ++e)
        for (size_t x = 0; x < w; ++x) {
            const size_t a = e * w + x, b = ((e + 1) % h) * w + x;
            const double d = 0.5 * (slopePerTexel[a].y + slopePerTexel[b].y);
            div[a].re += d;
            div[b].re -= d;
        }
    return div;
}

void requireTexels(size_t count, uint32_t w, uint32_t h, const char* what) {
    if (count != size_t(w) * size_t(h))
        throw std::invalid_argument(std::string(what) + ": " + std::to_string(count) +
                                    " texels for " + std::to_string(w) + " x " + std::to_string(h));
}

// ---------------------------------------------------------------------------------------------
// Horizon scan

// One sample of the scan, relative to the texel: the texel offset of the bilinear footprint's
// corner, the weights towards +column and +row, and 1 / distance.
struct ScanTap {
    int32_t dx = 0, dy = 0;
    float fx = 0.0f, fy = 0.0f;
    float inverseDistance = 0.0f;
};

// The tap at offset (px, py), `distance` texels away; snapped to whole texels where the
// direction is an axis (cos(pi/2) is 6e-17), so the scan keeps the map's symmetries.
ScanTap scanTap(double px, double py, double distance) {
    const auto snap = [](double v) {
        return std::fabs(v - std::round(v)) < 1e-9 ? std::round(v) : v;
    };
    px = snap(px);
    py = snap(py);
    const double x0 = std::floor(px), y0 = std::floor(py);
    ScanTap tap;
    tap.dx = int32_t(x0);
    tap.dy = int32_t(y0);
    tap.fx = static_cast<float>(px - x0);
    tap.fy = static_cast<float>(py - y0);
    tap.inverseDistance = static_cast<float>(1.0 / distance);
    return tap;
}

// Where index i (which may lie outside [0, n)) reads, for i in [-pad, n + pad).
std::vector<uint32_t> wrappedIndices(int32_t n, int32_t pad, CavityWrap wrap) {
    std::vector<uint32_t> table(size_t(n + 2 * pad));
    for (int32_t i = -pad; i < n + pad; ++i) {
        int32_t m = 0;
        if (wrap == CavityWrap::kClamp) {
            m = std::clamp(i, 0, n - 1);
        } else {
            m = i % n;
            if (m < 0) m += n;
        }
        table[size_t(i + pad)] = uint32_t(m);
    }
    return table;
}

// The highest of a line's windows of `window` values: out[i] = max(in[i .. i + window - 1]),
// in O(1) a value (van Herk 1992, "A fast algorithm for local minimum and maximum filters on
// rectangular and octagonal kernels"; Gil and Werman 1993, "Computing 2-D Min, Median, and Max
// Filters"): block-wise prefix and suffix maxima.
void windowMaxima(const std::vector<float>& in, size_t window, std::vector<float>& prefix,
                  std::vector<float>& suffix, float* out) {
    const size_t n = in.size();
    prefix.resize(n);
    suffix.resize(n);
    for (size_t i = 0; i < n; ++i)
        prefix[i] = i % window == 0 ? in[i] : std::max(prefix[i - 1], in[i]);
    for (size_t i = n; i-- > 0;)
        suffix[i] =
            (i % window == window - 1 || i == n - 1) ? in[i] : std::max(suffix[i + 1], in[i]);
    for (size_t i = 0; i + window <= n; ++i) out[i] = std::max(suffix[i], prefix[i + window - 1]);
}

// The highest texel of the field, as continued past the border, within `reach` texels of each
// texel along both axes (a square window); reach <= pad, the index tables' margin.
std::vector<float> highestAround(const std::vector<float>& field, int32_t w, int32_t h,
                                 int32_t reach, int32_t pad, const std::vector<uint32_t>& columns,
                                 const std::vector<uint32_t>& rows) {
    const size_t window = size_t(2 * reach + 1);
    std::vector<float> alongRows(field.size()), out(field.size());
    parallelFor(int32_t(0), h, [&](int32_t y) {
        std::vector<float> line(size_t(w + 2 * reach)), prefix, suffix,
            maxima(static_cast<size_t>(w));
        for (int32_t i = 0; i < w + 2 * reach; ++i)
            line[size_t(i)] = field[size_t(y) * size_t(w) + columns[size_t(i - reach + pad)]];
        windowMaxima(line, window, prefix, suffix, maxima.data());
        std::copy(maxima.begin(), maxima.end(), alongRows.begin() + std::ptrdiff_t(y) * w);
    });
    parallelFor(int32_t(0), w, [&](int32_t x) {
        std::vector<float> line(size_t(h + 2 * reach)), prefix, suffix,
            maxima(static_cast<size_t>(h));
        for (int32_t i = 0; i < h + 2 * reach; ++i)
            line[size_t(i)] =
                alongRows[size_t(rows[size_t(i - reach + pad)]) * size_t(w) + size_t(x)];
        windowMaxima(line, window, prefix, suffix, maxima.data());
        for (int32_t y = 0; y < h; ++y) out[size_t(y) * size_t(w) + size_t(x)] = maxima[size_t(y)];
    });
    return out;
}

}  // namespace

glm::dvec2 heightSlopeFromNormal(glm::vec3 n) {
    const double x = double(n.x), y = double(n.y), z = double(n.z);
    const double length = std::sqrt(x * x + y * y + z * z);
    if (!std::isfinite(length) || !(z > 0.0)) return glm::dvec2(0.0);
    const double nz = std::max(z / length, double(kMinNormalZ));
    return glm::dvec2(-(x / length) / nz, -(y / length) / nz);
}

HeightField heightFromNormals(const TangentNormalMap& normals, CavityWrapModes wrap,
                              float depthScale) {
    requireTexels(normals.normals.size(), normals.width, normals.height, "heightFromNormals");
    HeightField out;
    out.width = normals.width;
    out.height = normals.height;
    const size_t w = normals.width, h = normals.height;
    if (w == 0 || h == 0) return out;

    // Slopes per texel as (dh/dcolumn, dh/drow): y up is row down.
    std::vector<glm::dvec2> slopes(w * h);
    for (size_t i = 0; i < w * h; ++i) {
        const glm::dvec2 s = heightSlopeFromNormal(normals.normals[i]);
        slopes[i] = glm::dvec2(s.x, -s.y);
    }
    std::vector<Complex> field = slopeDivergence(slopes, w, h, wrap);

    const AxisTransform alongRow(w, wrap.u), alongColumn(h, wrap.v);
    // Rows: forward transform in place.
    parallelFor(size_t(0), h, [&](size_t y) {
        std::vector<Complex> work(alongRow.workSize());
        alongRow.forward(&field[y * w], work.data());
    });
    // Columns: forward, divide by the eigenvalue of each mode, back.
    parallelFor(size_t(0), w, [&](size_t x) {
        std::vector<Complex> line(h), work(alongColumn.workSize());
        for (size_t y = 0; y < h; ++y) line[y] = field[y * w + x];
        alongColumn.forward(line.data(), work.data());
        for (size_t y = 0; y < h; ++y) {
            const double lambda = alongRow.eigenvalue(x) + alongColumn.eigenvalue(y);
            line[y] = (x == 0 && y == 0) ? Complex{} : line[y] * (1.0 / lambda);
        }
        alongColumn.inverse(line.data(), work.data());
        for (size_t y = 0; y < h; ++y) field[y * w + x] = line[y];
    });
    out.heights.resize(w * h);
    const double scale = double(depthScale);
    parallelFor(size_t(0), h, [&](size_t y) {
        std::vector<Complex> work(alongRow.workSize());
        alongRow.inverse(&field[y * w], work.data());
        for (size_t x = 0; x < w; ++x)
            out.heights[y * w + x] = static_cast<float>(field[y * w + x].re * scale);
    });
    return out;
}

CavityMap cavityFromHeight(const HeightField& height, CavityWrapModes wrap,
                           const HorizonScan& scan) {
    requireTexels(height.heights.size(), height.width, height.height, "cavityFromHeight");
    if (scan.azimuths < 1 || scan.azimuths > kMaxAzimuths)
        throw std::invalid_argument("cavityFromHeight: azimuths " + std::to_string(scan.azimuths) +
                                    " outside 1 .. " + std::to_string(kMaxAzimuths));
    if (!(scan.radius >= 0.0f && scan.radius <= kMaxRadius))
        throw std::invalid_argument("cavityFromHeight: radius outside 0 .. 4096 texels");
    CavityMap out;
    out.width = height.width;
    out.height = height.height;
    const int32_t w = int32_t(height.width), h = int32_t(height.height);
    out.cavity.assign(size_t(w) * size_t(h), 1.0f);
    if (w == 0 || h == 0) return out;

    const uint32_t steps = uint32_t(std::floor(scan.radius));
    const uint32_t azimuths = scan.azimuths;
    // Per azimuth: the taps at t = 1 .. steps, and the two at t = +-1 for the tangent's rise.
    std::vector<ScanTap> taps(size_t(azimuths) * steps);
    std::vector<ScanTap> ahead(azimuths), behind(azimuths);
    for (uint32_t j = 0; j < azimuths; ++j) {
        const double phi = 2.0 * std::numbers::pi * double(j) / double(azimuths);
        const double cx = std::cos(phi), cy = std::sin(phi);
        for (uint32_t t = 1; t <= steps; ++t)
            taps[size_t(j) * steps + (t - 1)] = scanTap(double(t) * cx, double(t) * cy, double(t));
        ahead[j] = scanTap(cx, cy, 1.0);
        behind[j] = scanTap(-cx, -cy, 1.0);
    }
    const int32_t pad = int32_t(std::max(steps, 1u)) + 2;  // taps reach steps + 1 texels
    const std::vector<uint32_t> columns = wrappedIndices(w, pad, wrap.u);
    const std::vector<uint32_t> rows = wrappedIndices(h, pad, wrap.v);
    const float* field = height.heights.data();
    // Bilinear, of the field as continued past the border.
    const auto sampleAt = [&](int32_t x, int32_t y, const ScanTap& tap) {
        const size_t c0 = columns[size_t(x + tap.dx + pad)];
        const size_t c1 = columns[size_t(x + tap.dx + 1 + pad)];
        const size_t r0 = size_t(rows[size_t(y + tap.dy + pad)]) * size_t(w);
        const size_t r1 = size_t(rows[size_t(y + tap.dy + 1 + pad)]) * size_t(w);
        const float top = field[r0 + c0] + tap.fx * (field[r0 + c1] - field[r0 + c0]);
        const float bottom = field[r1 + c0] + tap.fx * (field[r1 + c1] - field[r1 + c0]);
        return top + tap.fy * (bottom - top);
    };
    // No sample rises above the highest texel it reads (bilinear weights are convex), and the
    // scan reads none farther than steps + 1 texels along either axis.
    const std::vector<float> highest =
        highestAround(height.heights, w, h, int32_t(steps) + 2, pad, columns, rows);

    parallelFor(int32_t(0), h, [&](int32_t y) {
        for (int32_t x = 0; x < w; ++x) {
            const float h0 = field[size_t(y) * size_t(w) + size_t(x)];
            const float headroom = highest[size_t(y) * size_t(w) + size_t(x)] - h0;
            float visible = 0.0f;
            for (uint32_t j = 0; j < azimuths; ++j) {
                // tan(e), the horizon's elevation: at least 0, and at least the rise of the
                // surface's own tangent along d (rays below it enter the surface at once; the
                // first tap, a texel away, misses it where the surface curves down). The rise
                // from the differences a texel ahead and behind, by their harmonic mean (van
                // Leer 1974, "Towards the Ultimate Conservative Difference Scheme II", the
                // monotone slope limiter): 0 unless both rise, so a crest or a plateau's edge
                // casts nothing on itself, and exact on a plane.
                const float rise = sampleAt(x, y, ahead[j]) - h0;
                const float fall = h0 - sampleAt(x, y, behind[j]);
                float steepest =
                    (rise > 0.0f && fall > 0.0f) ? 2.0f * rise * fall / (rise + fall) : 0.0f;
                const ScanTap* tap = taps.data() + size_t(j) * steps;
                for (uint32_t t = 0; t < steps; ++t, ++tap) {
                    // Nothing farther can rise above the horizon: stop (changes no result).
                    if (headroom * tap->inverseDistance <= steepest) break;
                    steepest =
                        std::max(steepest, (sampleAt(x, y, *tap) - h0) * tap->inverseDistance);
                }
                visible += 1.0f / (1.0f + steepest * steepest);  // cos^2(e)
            }
            out.cavity[size_t(y) * size_t(w) + size_t(x)] =
                std::min(1.0f, visible / float(azimuths));
        }
    });
    return out;
}

CavityMap cavityFromNormals(const TangentNormalMap& normals, const CavitySettings& settings) {
    return cavityFromHeight(heightFromNormals(normals, settings.wrap, settings.depthScale),
                            settings.wrap, settings.scan);
}

std::vector<CavityMap> cavityMipChain(const CavityMap& cavity) {
    requireTexels(cavity.cavity.size(), cavity.width, cavity.height, "cavityMipChain");
    std::vector<CavityMap> chain;
    if (cavity.width == 0 || cavity.height == 0) return chain;
    chain.push_back(cavity);
    while (chain.back().width > 1 || chain.back().height > 1) {
        const CavityMap& above = chain.back();
        CavityMap mip;
        mip.width = std::max(above.width >> 1, 1u);
        mip.height = std::max(above.height >> 1, 1u);
        mip.cavity.resize(size_t(mip.width) * mip.height);
        const uint32_t pw = above.width, ph = above.height;
        for (uint32_t y = 0; y < mip.height; ++y)
            for (uint32_t x = 0; x < mip.width; ++x) {
                const uint32_t x0 = std::min(2 * x, pw - 1), x1 = std::min(2 * x + 1, pw - 1);
                const uint32_t y0 = std::min(2 * y, ph - 1), y1 = std::min(2 * y + 1, ph - 1);
                const float* c = above.cavity.data();
                mip.cavity[size_t(y) * mip.width + x] =
                    0.25f * (c[size_t(y0) * pw + x0] + c[size_t(y0) * pw + x1] +
                             c[size_t(y1) * pw + x0] + c[size_t(y1) * pw + x1]);
            }
        chain.push_back(std::move(mip));
    }
    return chain;
}

uint8_t cavityToUnorm8(float cavity) {
    if (std::isnan(cavity)) return 255;
    return uint8_t(std::lround(std::clamp(cavity, 0.0f, 1.0f) * 255.0f));
}

std::vector<uint8_t> cavityToUnorm8(const CavityMap& cavity) {
    std::vector<uint8_t> bytes(cavity.cavity.size());
    for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = cavityToUnorm8(cavity.cavity[i]);
    return bytes;
}

}  // namespace onelight::bake
