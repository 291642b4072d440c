// onelight-lab brdf-report: speed against error for the specular models and for the
// environment "Fresnel" candidates. Writes DIR/README.md, CSVs and PNG plots.
//
// Error of a model: its shared float implementation against the double-precision exact
// height-correlated Smith BRDF of the same NDF (reference_brdf.hpp), on the albedo (F = 1) and
// on the lobe (relative L1 of f NoL). Cost: ns per evaluation of specularLobe on this CPU,
// measured with Google Benchmark in one run, with the model fixed at compile time as a shader
// specialization fixes it.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <thread>

#include "bake/parallel_for.hpp"
#include "commands.hpp"
#include "env_brdf.hpp"
#include "env_brdf_table.hpp"
#include "grids.hpp"
#include "microfacet_diffuse.hpp"
#include "plot.hpp"
#include "shading.hpp"
#include "world/file_write.hpp"

namespace onelight::lab {

namespace {

using namespace onelight::glsl;

// ------------------------------------------------------------------------------------------
// Cost

struct LobeInput {
    BrdfDots d;
    float gloss;
};

std::vector<LobeInput> randomLobeInputs() {
    std::mt19937 rng(2011);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<LobeInput> in(4096);
    for (LobeInput& x : in) {
        vec3 n(0, 0, 1);
        float cv = u(rng), cl = u(rng), pv = 2.0f * glsl::PI * u(rng),
              pl = 2.0f * glsl::PI * u(rng);
        float sv = std::sqrt(1 - cv * cv), sl = std::sqrt(1 - cl * cl);
        x.d = brdfDots(n, vec3(sv * std::cos(pv), sv * std::sin(pv), cv),
                       vec3(sl * std::cos(pl), sl * std::sin(pl), cl));
        x.gloss = u(rng);
    }
    return in;
}

class CollectingReporter : public benchmark::BenchmarkReporter {
public:
    std::map<std::string, double> nsPerEval;
    bool ReportContext(const Context&) override { return true; }
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) nsPerEval[r.benchmark_name()] = r.GetAdjustedRealTime();
    }
};

template <class Eval>
void registerCost(const std::string& name, const std::vector<LobeInput>& in, Eval eval) {
    benchmark::RegisterBenchmark(name.c_str(), [&in, eval](benchmark::State& state) {
        size_t i = 0;
        for (auto _ : state) {
            const LobeInput& x = in[i++ & 4095];
            float r = eval(x);
            benchmark::DoNotOptimize(r);
        }
    });
}

template <int NDF, int VIS>
float lobeOf(const LobeInput& x) {
    return specularLobe(NDF, VIS, FRESNEL_SCHLICK, vec3(0.04f), x.gloss, x.d).x;
}

// ns per evaluation of every model and env candidate, in one benchmark run.
std::map<std::string, double> measureCosts(const std::vector<LobeInput>& in,
                                           const std::vector<SplitSumTable>& tables, bool quick) {
    registerCost("lambert", in, [](const LobeInput& x) { return Fd_Lambert() * x.d.NoL; });
    registerCost("bp_none", in, lobeOf<NDF_BLINN_PHONG, VIS_NONE>);
    registerCost("bp_kelemen", in, lobeOf<NDF_BLINN_PHONG, VIS_KELEMEN>);
    registerCost("bp_schlick", in, lobeOf<NDF_BLINN_PHONG, VIS_SCHLICK_SMITH>);
    registerCost("beck_smith", in, lobeOf<NDF_BECKMANN, VIS_SMITH_CORRELATED>);
    registerCost("ggx_smith", in, lobeOf<NDF_GGX, VIS_SMITH_CORRELATED>);
    registerCost("env_blackops", in, [](const LobeInput& x) {
        vec2 e = EnvBRDF_BlackOps(x.d.NoV, x.gloss);
        return 0.04f * e.x + e.y;
    });
    registerCost("env_fit", in, [](const LobeInput& x) {
        vec2 e = EnvBRDF_Fit(x.d.NoV, x.gloss);
        return 0.04f * e.x + e.y;
    });
    for (const SplitSumTable& t : tables)
        registerCost("env_table" + std::to_string(t.resolution), in, [&t](const LobeInput& x) {
            ScaleBias e = t.sample(x.d.NoV, x.gloss);
            return float(0.04 * e.scale + e.bias);
        });
    // The material pipeline's pieces (docs/materials.md).
    registerCost("fd_chan", in, [](const LobeInput& x) {
        return Fd_Chan(x.d.NoV, x.d.NoL, x.d.LoH, x.d.NxH2, x.gloss) * x.d.NoL;
    });
    registerCost("lambert_weighted", in, [](const LobeInput& x) {
        const vec2 env = sampleEnvBrdfTable(envBrdfTableCoord(x.d.NoV, x.gloss));
        return diffuseEnergyWeight(MATERIAL_DIELECTRIC, vec3(0.04f), env).x * Fd_Lambert() *
               x.d.NoL;
    });
    registerCost("specular_occlusion", in, [](const LobeInput& x) {
        return specularOcclusion(x.d.NoV, x.d.NoL, ggxAlpha_fromGloss(x.gloss));
    });
    // A filtered normal fetch of length 0.58..1 (the dots as its components).
    registerCost("gloss_fold", in, [](const LobeInput& x) {
        return gloss_withFilteredNormal(x.gloss, vec3(x.d.NoV, x.d.NoL, x.d.LoH) * 0.57735f);
    });
    std::string minTime = std::string("--benchmark_min_time=") + (quick ? "0.02" : "0.3");
    char arg0[] = "onelight-lab";
    std::vector<char*> argv = {arg0, minTime.data()};
    int argc = int(argv.size());
    benchmark::Initialize(&argc, argv.data());
    CollectingReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::ClearRegisteredBenchmarks();
    return reporter.nsPerEval;
}

// ------------------------------------------------------------------------------------------
// Error

struct ModelPoint {
    double mu, gloss;
    ScaleBias shared, reference;
    double lobeError;
};

struct ModelSummary {
    std::string name;
    double ns = 0;
    double albedoMaxError = 0, albedoRmsError = 0;  // |A - A_ref| at F = 1
    double lobeMeanError = 0, lobeMaxError = 0;
    double maxAlbedo = 0, maxAlbedoMu = 0, maxAlbedoGloss = 0;
};

std::vector<ModelPoint> modelGrid(const SpecularModel& m, const std::vector<double>& mus,
                                  const std::vector<double>& glosses) {
    std::vector<ModelPoint> pts(mus.size() * glosses.size());
    bake::parallelFor(size_t(0), pts.size(), [&](size_t i) {
        double mu = mus[i % mus.size()], g = glosses[i / mus.size()];
        pts[i] = {mu, g, specularAlbedo(m, mu, g), referenceAlbedo(m, mu, g), lobeError(m, mu, g)};
    });
    return pts;
}

ModelSummary summarize(const SpecularModel& m, const std::vector<ModelPoint>& pts) {
    ModelSummary s;
    s.name = m.name;
    double sumSq = 0;
    for (const ModelPoint& p : pts) {
        double a = p.shared.albedo(1.0), e = std::abs(a - p.reference.albedo(1.0));
        s.albedoMaxError = std::max(s.albedoMaxError, e);
        sumSq += e * e;
        s.lobeMeanError += p.lobeError / pts.size();
        s.lobeMaxError = std::max(s.lobeMaxError, p.lobeError);
        if (a > s.maxAlbedo) s.maxAlbedo = a, s.maxAlbedoMu = p.mu, s.maxAlbedoGloss = p.gloss;
    }
    s.albedoRmsError = std::sqrt(sumSq / pts.size());
    return s;
}

struct EnvSummary {
    std::string name, description;
    double ns = 0;
    EnvError error;
};

std::string machineDescription() {
    std::ifstream cpu("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(cpu, line))
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    std::ifstream loadFile("/proc/loadavg");
    std::string load = "unknown";
    loadFile >> load;
    return model + ", " + std::to_string(std::thread::hardware_concurrency()) +
           " threads, load average " + load + " at the start";
}

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

}  // namespace

int brdfReport(const std::string& dir, bool quick) {
    namespace fs = std::filesystem;
    fs::create_directories(dir);
    auto t0 = std::chrono::steady_clock::now();
    std::vector<double> mus = quick ? muGrid(4) : muGrid(12);
    std::vector<double> glosses = quick ? glossGrid(3) : glossGrid(10);

    // Errors of the specular models.
    std::vector<ModelSummary> models;
    std::ostringstream gridCsv;
    gridCsv << "model,mu,gloss,scale,bias,ref_scale,ref_bias,lobe_error\n";
    for (const SpecularModel& m : specularModels()) {
        std::fprintf(stderr, "brdf-report: integrating %s\n", std::string(m.name).c_str());
        std::vector<ModelPoint> pts = modelGrid(m, mus, glosses);
        for (const ModelPoint& p : pts)
            gridCsv << m.name << ',' << p.mu << ',' << p.gloss << ',' << p.shared.scale << ','
                    << p.shared.bias << ',' << p.reference.scale << ',' << p.reference.bias << ','
                    << p.lobeError << '\n';
        models.push_back(summarize(m, pts));
    }

    // Errors of the environment "Fresnel" candidates against the runtime model's albedo.
    const SpecularModel& runtime = findModel(kRuntimeModel);
    std::fprintf(stderr, "brdf-report: environment Fresnel truth and tables\n");
    std::vector<double> checkMu = checkGridMu(), checkGloss = checkGridGloss();
    if (quick) checkMu.resize(8), checkGloss.resize(6);
    std::vector<EnvSample> truth = envTruth(runtime, checkMu, checkGloss);
    std::vector<SplitSumTable> tables;
    for (int res : quick ? std::vector<int>{8} : std::vector<int>{8, 16, 32, 64})
        tables.push_back(buildSplitSumTable(runtime, res));
    std::vector<EnvSummary> env;
    env.push_back({"env_blackops", "Black Ops fit c + (1 - c)(1 - NoV)^5 / (4 - 3g)", 0,
                   envError(truth, [](double mu, double g) {
                       vec2 e = EnvBRDF_BlackOps(float(mu), float(g));
                       return ScaleBias{e.x, e.y};
                   })});
    for (const SplitSumTable& t : tables)
        env.push_back({"env_table" + std::to_string(t.resolution),
                       "split-sum table " + std::to_string(t.resolution) + "x" +
                           std::to_string(t.resolution) + ", bilinear, float texels",
                       0, envError(truth, [&t](double mu, double g) { return t.sample(mu, g); })});
    env.push_back({"env_fit", "least-squares fit, 27 terms (shaders/env_brdf_fit.glsl)", 0,
                   envError(truth, [](double mu, double g) {
                       vec2 e = EnvBRDF_Fit(float(mu), float(g));
                       return ScaleBias{e.x, e.y};
                   })});

    // Costs, all in one benchmark run.
    std::fprintf(stderr, "brdf-report: measuring costs\n");
    std::vector<LobeInput> inputs = randomLobeInputs();
    std::map<std::string, double> ns = measureCosts(inputs, tables, quick);
    for (ModelSummary& m : models) m.ns = ns[m.name];
    for (EnvSummary& e : env) e.ns = ns[e.name];

    // CSVs.
    std::ostringstream modelsCsv, envCsv;
    modelsCsv << "model,ns_per_eval,albedo_max_error,albedo_rms_error,lobe_mean_error,"
                 "lobe_max_error,max_albedo,max_albedo_mu,max_albedo_gloss\n";
    for (const ModelSummary& m : models)
        modelsCsv << m.name << ',' << m.ns << ',' << m.albedoMaxError << ',' << m.albedoRmsError
                  << ',' << m.lobeMeanError << ',' << m.lobeMaxError << ',' << m.maxAlbedo << ','
                  << m.maxAlbedoMu << ',' << m.maxAlbedoGloss << '\n';
    envCsv << "candidate,ns_per_eval,max_error,rms_error\n";
    for (const EnvSummary& e : env)
        envCsv << e.name << ',' << e.ns << ',' << e.error.max << ',' << e.error.rms << '\n';
    world::writeFileAtomically(dir + "/models.csv", modelsCsv.str());
    world::writeFileAtomically(dir + "/models_grid.csv", gridCsv.str());
    world::writeFileAtomically(dir + "/env_fresnel.csv", envCsv.str());

    // Plots: cost on x, error on y, so the Pareto front shows.
    Plot pm{"Specular models: cost against error (vs exact Smith of the same NDF)",
            "ns per evaluation (CPU)",
            "mean lobe error (relative L1)",
            false,
            true,
            {}};
    for (size_t i = 0; i < models.size(); ++i)
        pm.series.push_back({models[i].name,
                             seriesColor(int(i)),
                             {{models[i].ns, models[i].lobeMeanError}},
                             false,
                             true});
    writePlotPng(dir + "/models_cost_vs_error.png", pm);
    Plot pa = pm;
    pa.title = "Specular models: cost against albedo error (F = 1)";
    pa.yLabel = "max albedo error";
    for (size_t i = 0; i < models.size(); ++i)
        pa.series[i].points = {{models[i].ns, models[i].albedoMaxError}};
    writePlotPng(dir + "/models_cost_vs_albedo_error.png", pa);
    Plot pe{
        "Environment Fresnel: cost against error (vs integrated " + std::string(runtime.name) + ")",
        "ns per evaluation (CPU)",
        "max albedo error, f0 in {0.04, 1}",
        false,
        true,
        {}};
    for (size_t i = 0; i < env.size(); ++i)
        pe.series.push_back(
            {env[i].name, seriesColor(int(i)), {{env[i].ns, env[i].error.max}}, false, true});
    writePlotPng(dir + "/env_cost_vs_error.png", pe);
    Plot pc{"Specular albedo at gloss 0.5 (F = 1)", "NoV", "albedo", false, false, {}};
    for (size_t i = 0; i < specularModels().size(); ++i) {
        PlotSeries s{std::string(specularModels()[i].name), seriesColor(int(i)), {}, true, false};
        for (int k = 1; k <= (quick ? 4 : 24); ++k) {
            double mu = double(k) / (quick ? 4 : 24);
            s.points.emplace_back(mu, specularAlbedo(specularModels()[i], mu, 0.5).albedo(1.0));
        }
        pc.series.push_back(s);
    }
    writePlotPng(dir + "/albedo_gloss05.png", pc);

    // README.
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::ostringstream md;
    md << "# BRDF speed against error\n\n"
       << "Generated by `build/bin/onelight-lab brdf-report -o docs/brdf-report` on "
       << machineDescription() << " in " << fmt("%.0f", seconds) << " s. Costs are ns per "
       << "evaluation of the shared `shaders/brdf.glsl` code compiled as C++ (float, the model "
       << "fixed at compile time as a specialization constant fixes it), measured with Google "
       << "Benchmark in one run; compare them as ratios. Errors are computed by adaptive "
       << "Gauss-Kronrod integration over half vectors (`bake/lab/albedo.hpp`) on " << mus.size()
       << " NoV x " << glosses.size() << " gloss values.\n\n"
       << "## Specular models\n\n"
       << "Reference: the exact height-correlated Smith BRDF of the same NDF in double precision "
          "(`bake/lab/reference_brdf.hpp`; Blinn-Phong's Lambda, which has no closed form, is "
          "integrated from the projected-area identity). "
          "For `beck_smith` and `ggx_smith` the error is therefore that of the float "
          "implementation alone. Albedo error is |A - A_ref| with F = 1; lobe error is "
          "int |f - f_ref| NoL dl / int f_ref NoL dl. Max albedo is the white-furnace maximum "
          "(F = 1) over the grid.\n\n"
       << "| model | ns/eval | x Lambert | albedo max err | albedo RMS err | lobe mean err | lobe "
          "max err | max albedo (NoV, gloss) |\n|---|---|---|---|---|---|---|---|\n";
    for (const ModelSummary& m : models)
        md << "| " << m.name << " | " << fmt("%.2f", m.ns) << " | "
           << fmt("%.1f", m.ns / ns["lambert"]) << " | " << fmt("%.2e", m.albedoMaxError) << " | "
           << fmt("%.2e", m.albedoRmsError) << " | " << fmt("%.2e", m.lobeMeanError) << " | "
           << fmt("%.2e", m.lobeMaxError) << " | " << fmt("%.4f", m.maxAlbedo) << " ("
           << fmt("%.3g", m.maxAlbedoMu) << ", " << fmt("%.2g", m.maxAlbedoGloss) << ") |\n";
    md << "\nLambert (`Fd_Lambert() * NoL`): " << fmt("%.2f", ns["lambert"]) << " ns/eval.\n\n"
       << "![models](models_cost_vs_error.png)\n\n![albedo](models_cost_vs_albedo_error.png)\n\n"
       << "![albedo at gloss 0.5](albedo_gloss05.png)\n\n"
       << "## Environment \"Fresnel\"\n\n"
       << "Truth: the directional albedo f0 * scale + bias of `" << runtime.name
       << "` (the runtime model), integrated at " << truth.size()
       << " points that lie off the tables' texel centres and off the fit's grid. Error: "
          "|candidate - truth| of the albedo for f0 = 0.04 and f0 = 1. A table costs one texture "
          "fetch on the GPU; its CPU figure is the cost of emulating the bilinear fetch.\n\n"
       << "| candidate | what | ns/eval | max error | RMS error |\n|---|---|---|---|---|\n";
    for (const EnvSummary& e : env)
        md << "| " << e.name << " | " << e.description << " | " << fmt("%.2f", e.ns) << " | "
           << fmt("%.2e", e.error.max) << " | " << fmt("%.2e", e.error.rms) << " |\n";
    md << "\n![env](env_cost_vs_error.png)\n\n";

    // The choice the tables justify: the cheapest model whose error is float rounding.
    const ModelSummary* exact = nullptr;
    const ModelSummary* cheapest = &models.front();
    for (const ModelSummary& m : models) {
        if (m.ns < cheapest->ns) cheapest = &m;
        if (m.lobeMaxError < 1e-5 && (!exact || m.ns < exact->ns)) exact = &m;
    }
    const EnvSummary* bestTable = nullptr;
    for (const EnvSummary& e : env)
        if (e.name.rfind("env_table", 0) == 0 && (!bestTable || e.error.rms < bestTable->error.rms))
            bestTable = &e;
    md << "## What the tables justify\n\n";
    if (exact)
        md << "- Runtime specular: `" << exact->name << "`, the cheapest model whose lobe error is "
           << "float rounding (" << fmt("%.1e", exact->lobeMaxError) << "). It costs "
           << fmt("%.2f", exact->ns / cheapest->ns) << "x the cheapest model (`" << cheapest->name
           << "`, lobe error " << fmt("%.2f", cheapest->lobeMeanError) << " on average).\n";
    if (bestTable)
        md << "- Environment \"Fresnel\": a split-sum table (`" << bestTable->name << "`: RMS "
           << fmt("%.1e", bestTable->error.rms) << ", max " << fmt("%.1e", bestTable->error.max)
           << ") where a texture fetch is affordable; `env_fit` (RMS "
           << fmt("%.1e", env.back().error.rms)
           << ", no texture) otherwise. The Black Ops curve is "
           << fmt("%.0f", env.front().error.rms / env.back().error.rms) << "x worse in RMS than "
           << "the fit: it was made for Blinn-Phong with Schlick-Smith, not GGX.\n"
           << "- The max errors of every candidate sit at grazing angles on glossy surfaces, "
           << "where the albedo drops over a NoV range of about alpha (0.003 at gloss 1).\n\n";
    // The diffuse models against Lambertian microfacets with multiple scattering (a random walk,
    // microfacet_diffuse.hpp), with their costs.
    DiffuseComparisonGrid grid;
    if (quick) grid.walks.count = 2048;
    const DiffuseReference reference = buildDiffuseReference(grid);
    const std::vector<DiffuseModelError> lambertError =
        measureDiffuseModel(lambertDiffuse(), reference);
    const std::vector<DiffuseModelError> chanError = measureDiffuseModel(chanDiffuse(), reference);
    md << "## Material pipeline pieces\n\n"
       << "Diffuse models against Lambertian microfacets under the GGX NDF with multiple "
          "scattering (the stochastic random walk of Heitz et al. 2016, "
       << grid.walks.count
       << " walks per point; albedo 1; view and light at 0..80 degrees, 4 azimuths): RMS of the "
          "relative error of f over the grid.\n\n"
       << "| model | ns/eval | x Lambert |";
    for (const DiffuseModelError& e : lambertError) md << " gloss " << fmt("%.2f", e.gloss) << " |";
    md << "\n|---|---|---|";
    for (size_t i = 0; i < lambertError.size(); ++i) md << "---|";
    md << "\n| `Fd_Lambert` | " << fmt("%.2f", ns["lambert"]) << " | 1.0 |";
    for (const DiffuseModelError& e : lambertError)
        md << " " << fmt("%.3f", e.rmsRelativeError) << " |";
    md << "\n| `Fd_Chan` | " << fmt("%.2f", ns["fd_chan"]) << " | "
       << fmt("%.1f", ns["fd_chan"] / ns["lambert"]) << " |";
    for (const DiffuseModelError& e : chanError)
        md << " " << fmt("%.3f", e.rmsRelativeError) << " |";
    md << "\n\nEnergy conservation (`diffuseEnergyWeight`, the split-sum table's bilinear lookup "
          "and "
          "the weight, times Lambert): "
       << fmt("%.2f", ns["lambert_weighted"]) << " ns/eval ("
       << fmt("%.1f", ns["lambert_weighted"] / ns["lambert"])
       << "x Lambert on the CPU; one texture fetch on the GPU, shared with the probes). Specular "
          "occlusion (`specularOcclusion`): "
       << fmt("%.2f", ns["specular_occlusion"])
       << " ns/eval. The runtime fold of a filtered normal fetch into gloss "
          "(`gloss_withFilteredNormal`, on every normal-mapped pixel): "
       << fmt("%.2f", ns["gloss_fold"])
       << " ns/eval. Their errors (the white furnace within 0.4%, the visibility cone within 0.24 "
          "on average, the fold within 4.6e-4 in gloss of the double tables) and those of the "
          "normal and gloss mips are in docs/materials.md.\n\n";
    md << "Cost and error are measured; the Pareto front is the lower left of each plot.\n\n"
       << "CSV: `models.csv` (summary), `models_grid.csv` (every grid point), "
          "`env_fresnel.csv`.\n";
    world::writeFileAtomically(dir + "/README.md", md.str());
    std::fprintf(stderr, "brdf-report: wrote %s/README.md in %.0f s\n", dir.c_str(), seconds);
    return 0;
}

}  // namespace onelight::lab
