// Reference BRDF of a rough surface made of Lambertian microfacets under the GGX NDF, with
// multiple scattering between the microfacets: the stochastic evaluation of Heitz, Hanika,
// d'Eon and Dachsbacher 2016, "Multiple-Scattering Microfacet BSDFs with the Smith Model", for
// their diffuse microsurface. Light does a random walk on a Smith microsurface (heights and
// normals uncorrelated): free paths from the Smith height distribution and GGX's Lambda, a
// microfacet hit drawn from the visible normals of the incoming direction, Lambertian scattering
// about it. Every walk leaves the surface eventually, so with microfacet albedo 1 the BRDF
// conserves energy exactly, and it is reciprocal.
//
// And the measurement of analytic diffuse models (Fd_Lambert, Fd_Chan of shaders/brdf.glsl)
// against it.
//
// Everything is deterministic: each walk draws from its own generator seeded by (seed, walk
// index), walks are summed in blocks of fixed size and the blocks in index order, so the result
// is bit-identical for any number of threads.
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

namespace onelight::lab {

// A unit vector in the frame of the macro surface: z is its normal.
struct Direction {
    double x, y, z;
};

// polar angle theta from the normal, azimuth phi, in radians.
[[nodiscard]] Direction directionFromAngles(double theta, double phi);

// The microsurface: isotropic GGX normals of roughness alpha (Walter et al. 2007, eq. 33), each
// facet Lambertian of albedo rho.
struct MicrofacetDiffuse {
    double alpha;
    double albedo = 1.0;
};

struct RandomWalks {
    int count;  // > 0
    std::uint64_t seed = 1;
    // A walk still on the surface after this many scattering events is cut (and counted).
    int maxScatteringOrder = 1000;
};

// A Monte Carlo mean and its standard error (sample standard deviation / sqrt(walks)).
struct Estimate {
    double mean = 0.0;
    double standardError = 0.0;
};

// The BRDF f(wi, wo) itself, in 1/sr (the walk estimates f cos(theta_o); it is divided by
// wo.z), split by scattering order: single (order 1), multiple (orders >= 2), total. Each with
// its own standard error from the per-walk values.
struct MicrofacetDiffuseBrdf {
    Estimate single, multiple, total;
    int truncatedWalks = 0;
};

// wi, wo unit vectors with z > 0. wi is where the light comes from (the walk starts at -wi);
// wo is the direction the next-event estimates look towards.
[[nodiscard]] MicrofacetDiffuseBrdf estimateMicrofacetDiffuseBrdf(const MicrofacetDiffuse& surface,
                                                                  Direction wi, Direction wo,
                                                                  const RandomWalks& walks);

// Directional albedo for light from wi, two independent ways:
//  - escaped: the energy (rho^k after k scattering events) of walks when they leave the surface
//    above the macro surface; total is exactly 1 at rho = 1 (less any truncated walk);
//  - integratedLobe: int f(wi, wo) cos(theta_o) dwo, with one wo per walk drawn uniformly over
//    the hemisphere and the walk's next-event estimate towards it: tests that the BRDF
//    estimator is consistent with the walk (energy conservation at rho = 1).
// single counts order 1 only. Each uses `walks.count` walks (different ones).
struct ScatteringOrders {
    Estimate single, total;
};
struct MicrofacetDiffuseAlbedo {
    ScatteringOrders escaped, integratedLobe;
    int truncatedWalks = 0;
};
[[nodiscard]] MicrofacetDiffuseAlbedo estimateMicrofacetDiffuseAlbedo(
    const MicrofacetDiffuse& surface, Direction wi, const RandomWalks& walks);

// ---------------------------------------------------------------------------------------------
// Analytic diffuse models against the reference.

// f per unit albedo, in 1/sr, of the dot products of shaders/brdf.glsl's brdfDots.
using DiffuseFunction =
    std::function<double(double NoV, double NoL, double LoH, double NxH2, double gloss)>;
struct DiffuseModel {
    std::string_view name;
    DiffuseFunction f;
};
// The shared float pieces Fd_Lambert and Fd_Chan (inputs clamped as brdfDots clamps them).
[[nodiscard]] DiffuseModel lambertDiffuse();
[[nodiscard]] DiffuseModel chanDiffuse();

// The grid the models are measured on: for each gloss (GGX alpha = ggxAlpha(gloss), Chan 2018
// eq. 2), every view and light polar angle and relative azimuth (azimuth 0: light and view on
// the same side, i.e. retro-reflection when the polar angles match). A polar angle of 0 takes
// one azimuth only.
struct DiffuseComparisonGrid {
    std::vector<double> glosses{0.0, 0.25, 0.5, 0.75, 1.0};
    std::vector<double> viewPolarDegrees{0.0, 30.0, 50.0, 65.0, 80.0};
    std::vector<double> lightPolarDegrees{0.0, 30.0, 50.0, 65.0, 80.0};
    std::vector<double> azimuthDegrees{0.0, 60.0, 120.0, 180.0};
    RandomWalks walks{16384, 2016};
};

// The reference (rho = 1) on the grid: the BRDF at every point and the directional albedo for
// every (gloss, view).
struct DiffuseReferencePoint {
    double gloss;
    Direction view, light;
    Estimate f;
};
struct DiffuseReferenceAlbedo {
    double gloss, viewPolarDegrees;
    MicrofacetDiffuseAlbedo albedo;  // escaped.total is 1 up to truncated walks
};
struct DiffuseReference {
    DiffuseComparisonGrid grid;
    std::vector<DiffuseReferencePoint> points;
    std::vector<DiffuseReferenceAlbedo> albedos;
};
[[nodiscard]] DiffuseReference buildDiffuseReference(const DiffuseComparisonGrid& grid);

// A model's error at one gloss. relative error = (f_model - f_ref) / f_ref at each point;
// referenceNoiseRms is the RMS of the reference's relative standard errors, the floor under
// rmsRelativeError that Monte Carlo noise alone would give. The model's directional albedo is
// int f NoL dl by adaptive quadrature, for each view polar angle of the grid.
struct DiffuseModelError {
    double gloss;
    double rmsRelativeError, maxAbsRelativeError, referenceNoiseRms;
    double minAlbedo, maxAlbedo;  // of the model, over the views
    double maxAbsAlbedoError;     // max over views of |A_model - A_reference| (escaped energy)
};
// One entry per gloss of the reference's grid, in its order.
[[nodiscard]] std::vector<DiffuseModelError> measureDiffuseModel(const DiffuseModel& model,
                                                                 const DiffuseReference& reference);

// The model's directional albedo int f(v, l) NoL dl for a view at polar angle theta (radians).
[[nodiscard]] double diffuseModelAlbedo(const DiffuseModel& model, double gloss, double theta);

}  // namespace onelight::lab
