#include "world/regions/region_split.hpp"

#include <algorithm>
#include <map>
#include <tuple>

// OpenMesh default-constructs vector properties uninitialised by design; GCC's
// -Wmaybe-uninitialized flags that inside its headers under the sanitizers.
#pragma GCC diagnostic push
#if !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#pragma GCC diagnostic pop

namespace onelight::world {
namespace {

struct RegionTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
};
using RegionMesh = OpenMesh::TriMesh_ArrayKernelT<RegionTraits>;

constexpr uint32_t kBoundary = 0xFFFFFFFEu;  // vertex label: on a cut, belongs to both sides
constexpr uint32_t kUnlit = kNoIndex;        // no primary reaches the point

/// Evaluates the dominant primary, reusing one scratch buffer.
struct Dominance {
    const PrimaryIlluminanceFn& illuminance;
    std::vector<double> scratch;
    uint32_t at(const glm::dvec3& p, const glm::vec3& n) {
        std::fill(scratch.begin(), scratch.end(), 0.0);
        illuminance(p, n, scratch);
        return dominantPrimary(scratch);
    }
    uint32_t at(const CompileVertex& v) { return at(v.position, v.normal); }
};

CompileVertex centroidOf(const CompileVertex& a, const CompileVertex& b, const CompileVertex& c) {
    return interpolate(interpolate(a, b, 0.5), c, 1.0 / 3.0);
}

bool positionLess(const glm::dvec3& x, const glm::dvec3& y) {
    return std::tie(x.x, x.y, x.z) < std::tie(y.x, y.y, y.z);
}

/// Splits the triangles of one mesh instance (indices into geometry.triangles).
class InstanceSplitter {
public:
    InstanceSplitter(StaticGeometry& geometry, Dominance& dominance, const RegionOptions& options,
                     RegionStats& stats)
        : geometry_(geometry), dominance_(dominance), options_(options), stats_(stats) {
        mesh_.add_property(vertexId_);
        mesh_.add_property(vertexLabel_);
        mesh_.add_property(faceLabel_);
    }

    std::vector<StaticTriangle> run(const std::vector<StaticTriangle>& triangles) {
        template_ = triangles.front();
        build(triangles);
        splitFacesAroundInnerRegions();
        cutEdges();
        labelFaces();
        mergeSmallFragments();
        std::vector<StaticTriangle> out;
        for (RegionMesh::FaceHandle f : mesh_.faces()) {
            StaticTriangle t = template_;
            int k = 0;
            for (RegionMesh::VertexHandle v : mesh_.fv_range(f))
                t.v[static_cast<size_t>(k++)] = mesh_.property(vertexId_, v);
            t.primary = mesh_.property(faceLabel_, f);
            out.push_back(t);
        }
        for (StaticTriangle t : unmeshed_) {
            t.primary = fallbackLabel(centroidLabel(t.v));
            out.push_back(t);
        }
        return out;
    }

private:
    RegionMesh::VertexHandle add_vertex(uint32_t id, uint32_t label) {
        const glm::dvec3& p = geometry_.vertices[id].position;
        const RegionMesh::VertexHandle v = mesh_.add_vertex(RegionMesh::Point(p.x, p.y, p.z));
        mesh_.property(vertexId_, v) = id;
        mesh_.property(vertexLabel_, v) = label;
        return v;
    }

    uint32_t labelOfVertex(uint32_t id) {
        const auto found = labels_.find(id);
        if (found != labels_.end()) return found->second;
        const uint32_t label = dominance_.at(geometry_.vertices[id]);
        labels_.emplace(id, label);
        return label;
    }

    void build(const std::vector<StaticTriangle>& triangles) {
        std::map<uint32_t, RegionMesh::VertexHandle> handleOf;
        for (const StaticTriangle& t : triangles) {
            std::array<RegionMesh::VertexHandle, 3> corners;
            for (size_t k = 0; k < 3; ++k) {
                auto it = handleOf.find(t.v[k]);
                if (it == handleOf.end())
                    it = handleOf.emplace(t.v[k], add_vertex(t.v[k], labelOfVertex(t.v[k]))).first;
                corners[k] = it->second;
            }
            if (mesh_.add_face(corners[0], corners[1], corners[2]).is_valid()) continue;
            // Non-manifold here: give the triangle its own corners.
            for (size_t k = 0; k < 3; ++k) corners[k] = add_vertex(t.v[k], labelOfVertex(t.v[k]));
            if (!mesh_.add_face(corners[0], corners[1], corners[2]).is_valid())
                unmeshed_.push_back(t);
        }
    }

    std::array<RegionMesh::VertexHandle, 3> cornersOf(RegionMesh::FaceHandle f) const {
        std::array<RegionMesh::VertexHandle, 3> c;
        int k = 0;
        for (RegionMesh::VertexHandle v : mesh_.fv_range(f)) c[static_cast<size_t>(k++)] = v;
        return c;
    }

    uint32_t centroidLabel(const std::array<uint32_t, 3>& ids) {
        return dominance_.at(centroidOf(geometry_.vertices[ids[0]], geometry_.vertices[ids[1]],
                                        geometry_.vertices[ids[2]]));
    }

    uint32_t fallbackLabel(uint32_t label) { return label == kUnlit ? 0u : label; }

    /// A region that lies inside one triangle (a spot pool on a big floor) leaves all three
    /// corners agreeing. Samples the centres of a regular subdivision of the triangle (spacing
    /// about options.sampleSpacing) and splits the triangle at the first that disagrees.
    void splitFacesAroundInnerRegions() {
        std::vector<RegionMesh::FaceHandle> faces(mesh_.faces_begin(), mesh_.faces_end());
        for (RegionMesh::FaceHandle f : faces) {
            const auto c = cornersOf(f);
            const uint32_t l0 = mesh_.property(vertexLabel_, c[0]);
            if (l0 != mesh_.property(vertexLabel_, c[1]) ||
                l0 != mesh_.property(vertexLabel_, c[2]))
                continue;
            const CompileVertex& a = geometry_.vertices[mesh_.property(vertexId_, c[0])];
            const CompileVertex& b = geometry_.vertices[mesh_.property(vertexId_, c[1])];
            const CompileVertex& d = geometry_.vertices[mesh_.property(vertexId_, c[2])];
            const double longest = std::max({glm::length(b.position - a.position),
                                             glm::length(d.position - b.position),
                                             glm::length(a.position - d.position)});
            const uint32_t n =
                static_cast<uint32_t>(std::clamp(std::ceil(longest / options_.sampleSpacing), 1.0,
                                                 double(options_.maxSamplesPerEdge)));
            bool split = false;
            for (uint32_t i = 0; i < n && !split; ++i) {
                for (uint32_t j = 0; i + j < n && !split; ++j) {
                    // Centre of the upward sub-triangle (i, j): barycentric ((i + 1/3) / n, (j +
                    // 1/3) / n).
                    const double u = (i + 1.0 / 3.0) / n, v = (j + 1.0 / 3.0) / n;
                    const CompileVertex alongAb =
                        interpolate(a, b, u + v > 0.0 ? v / (u + v) : 0.0);
                    const CompileVertex sample = interpolate(d, alongAb, u + v);
                    const uint32_t label = dominance_.at(sample);
                    if (label == l0 || label == kUnlit) continue;
                    geometry_.vertices.push_back(sample);
                    const uint32_t id = static_cast<uint32_t>(geometry_.vertices.size() - 1);
                    labels_.emplace(id, label);
                    mesh_.split(f, add_vertex(id, label));
                    ++stats_.facesCentreSplit;
                    split = true;
                }
            }
        }
    }

    /// Cuts every edge whose ends have different (lit) primaries at the switch point.
    void cutEdges() {
        std::vector<RegionMesh::EdgeHandle> edges(mesh_.edges_begin(), mesh_.edges_end());
        for (RegionMesh::EdgeHandle e : edges) {
            const RegionMesh::HalfedgeHandle h = mesh_.halfedge_handle(e, 0);
            RegionMesh::VertexHandle va = mesh_.from_vertex_handle(h),
                                     vb = mesh_.to_vertex_handle(h);
            uint32_t la = mesh_.property(vertexLabel_, va), lb = mesh_.property(vertexLabel_, vb);
            if (la == lb || la == kBoundary || lb == kBoundary || la == kUnlit || lb == kUnlit)
                continue;
            uint32_t ia = mesh_.property(vertexId_, va), ib = mesh_.property(vertexId_, vb);
            // Bisect in a canonical direction so coincident seam edges are cut at one point.
            if (positionLess(geometry_.vertices[ib].position, geometry_.vertices[ia].position)) {
                std::swap(ia, ib);
                std::swap(la, lb);
            }
            const CompileVertex a = geometry_.vertices[ia], b = geometry_.vertices[ib];
            const double length = glm::length(b.position - a.position);
            if (!(length > 2.0 * options_.boundaryTolerance)) continue;
            double lo = 0.0, hi = 1.0;
            for (int i = 0; i < 60 && (hi - lo) * length > options_.boundaryTolerance; ++i) {
                const double mid = 0.5 * (lo + hi);
                if (dominance_.at(interpolate(a, b, mid)) == la)
                    lo = mid;
                else
                    hi = mid;
            }
            const double t = 0.5 * (lo + hi);
            if (t * length < options_.boundaryTolerance ||
                (1.0 - t) * length < options_.boundaryTolerance)
                continue;
            geometry_.vertices.push_back(interpolate(a, b, t));
            const uint32_t id = static_cast<uint32_t>(geometry_.vertices.size() - 1);
            mesh_.split(e, add_vertex(id, kBoundary));
            ++stats_.edgesCut;
        }
    }

    void labelFaces() {
        for (RegionMesh::FaceHandle f : mesh_.faces()) {
            uint32_t label = kUnlit;
            bool conflict = false;
            std::array<uint32_t, 3> ids{};
            int k = 0;
            for (RegionMesh::VertexHandle v : mesh_.fv_range(f)) {
                ids[static_cast<size_t>(k++)] = mesh_.property(vertexId_, v);
                const uint32_t l = mesh_.property(vertexLabel_, v);
                if (l == kBoundary || l == kUnlit) continue;
                if (label != kUnlit && l != label) conflict = true;
                label = l;
            }
            if (conflict || label == kUnlit) label = centroidLabel(ids);
            mesh_.property(faceLabel_, f) = label;
        }
    }

    double edgeLength(RegionMesh::HalfedgeHandle h) const {
        const glm::dvec3& a =
            geometry_.vertices[mesh_.property(vertexId_, mesh_.from_vertex_handle(h))].position;
        const glm::dvec3& b =
            geometry_.vertices[mesh_.property(vertexId_, mesh_.to_vertex_handle(h))].position;
        return glm::length(b - a);
    }

    double faceArea(RegionMesh::FaceHandle f) const {
        const auto c = cornersOf(f);
        const glm::dvec3& a = geometry_.vertices[mesh_.property(vertexId_, c[0])].position;
        const glm::dvec3& b = geometry_.vertices[mesh_.property(vertexId_, c[1])].position;
        const glm::dvec3& d = geometry_.vertices[mesh_.property(vertexId_, c[2])].position;
        return 0.5 * glm::length(glm::cross(b - a, d - a));
    }

    /// Same-label connected components; relabels small or unlit ones into the neighbour with
    /// the longest shared border, smallest first, until nothing changes.
    void mergeSmallFragments() {
        for (int pass = 0; pass < 8; ++pass) {
            std::vector<int> component(mesh_.n_faces(), -1);
            std::vector<std::vector<RegionMesh::FaceHandle>> members;
            std::vector<double> area;
            for (RegionMesh::FaceHandle seed : mesh_.faces()) {
                if (component[static_cast<size_t>(seed.idx())] >= 0) continue;
                const int id = static_cast<int>(members.size());
                members.emplace_back();
                area.push_back(0.0);
                std::vector<RegionMesh::FaceHandle> stack{seed};
                component[static_cast<size_t>(seed.idx())] = id;
                const uint32_t label = mesh_.property(faceLabel_, seed);
                while (!stack.empty()) {
                    const RegionMesh::FaceHandle f = stack.back();
                    stack.pop_back();
                    members.back().push_back(f);
                    area.back() += faceArea(f);
                    for (RegionMesh::FaceHandle g : mesh_.ff_range(f)) {
                        if (component[static_cast<size_t>(g.idx())] >= 0 ||
                            mesh_.property(faceLabel_, g) != label)
                            continue;
                        component[static_cast<size_t>(g.idx())] = id;
                        stack.push_back(g);
                    }
                }
            }
            std::vector<size_t> order(members.size());
            for (size_t i = 0; i < order.size(); ++i) order[i] = i;
            std::stable_sort(order.begin(), order.end(),
                             [&](size_t a, size_t b) { return area[a] < area[b]; });
            bool changed = false;
            std::vector<uint8_t> touched(members.size(), 0);
            for (size_t c : order) {
                if (touched[c]) continue;
                const uint32_t label = mesh_.property(faceLabel_, members[c].front());
                if (!(area[c] < options_.minFragmentArea) && label != kUnlit) continue;
                std::map<uint32_t, double> border;
                for (RegionMesh::FaceHandle f : members[c]) {
                    for (RegionMesh::HalfedgeHandle h : mesh_.fh_range(f)) {
                        const RegionMesh::FaceHandle g = mesh_.opposite_face_handle(h);
                        if (!g.is_valid()) continue;
                        const uint32_t other = mesh_.property(faceLabel_, g);
                        if (other == label || other == kUnlit) continue;
                        border[other] += edgeLength(h);
                    }
                }
                if (border.empty()) continue;
                uint32_t best = border.begin()->first;
                for (const auto& [other, length] : border)
                    if (length > border[best]) best = other;
                for (RegionMesh::FaceHandle f : members[c]) mesh_.property(faceLabel_, f) = best;
                for (RegionMesh::FaceHandle f : members[c])
                    for (RegionMesh::FaceHandle g : mesh_.ff_range(f))
                        touched[static_cast<size_t>(component[static_cast<size_t>(g.idx())])] = 1;
                ++stats_.fragmentsMerged;
                changed = true;
            }
            if (!changed) break;
        }
        for (RegionMesh::FaceHandle f : mesh_.faces())
            mesh_.property(faceLabel_, f) = fallbackLabel(mesh_.property(faceLabel_, f));
    }

    StaticGeometry& geometry_;
    Dominance& dominance_;
    const RegionOptions& options_;
    RegionStats& stats_;
    RegionMesh mesh_;
    OpenMesh::VPropHandleT<uint32_t> vertexId_;
    OpenMesh::VPropHandleT<uint32_t> vertexLabel_;
    OpenMesh::FPropHandleT<uint32_t> faceLabel_;
    std::map<uint32_t, uint32_t> labels_;
    std::vector<StaticTriangle> unmeshed_;
    StaticTriangle template_;
};

}  // namespace

RegionStats assignPrimaryRegions(StaticGeometry& geometry, uint32_t primaryCount,
                                 const PrimaryIlluminanceFn& illuminance,
                                 const RegionOptions& options) {
    RegionStats stats;
    const size_t before = geometry.triangles.size();
    if (primaryCount == 0) {
        for (StaticTriangle& t : geometry.triangles) t.primary = kNoIndex;
        return stats;
    }
    Dominance dominance{illuminance, std::vector<double>(primaryCount, 0.0)};
    std::vector<StaticTriangle> out;
    out.reserve(geometry.triangles.size());
    size_t begin = 0;
    const std::vector<StaticTriangle> triangles = std::move(geometry.triangles);
    while (begin < triangles.size()) {
        // Triangles of one instance (and material) are contiguous after the split stage.
        size_t end = begin + 1;
        while (end < triangles.size() && triangles[end].instance == triangles[begin].instance &&
               triangles[end].material == triangles[begin].material)
            ++end;
        const uint32_t instance = triangles[begin].instance;
        if (instance < geometry.instanceIsProp.size() && geometry.instanceIsProp[instance]) {
            // A prop: not split; the primary dominant at its lighting origin, whichever way a
            // surface faces (a zero normal), for all of it.
            std::vector<double> at(primaryCount, 0.0);
            illuminance(geometry.instanceLightingOrigin[instance], glm::vec3(0.0f), at);
            const uint32_t primary = dominantPrimary(at);
            for (size_t t = begin; t < end; ++t) {
                out.push_back(triangles[t]);
                out.back().primary = primary;
            }
            begin = end;
            continue;
        }
        InstanceSplitter splitter(geometry, dominance, options, stats);
        const std::vector<StaticTriangle> group(
            triangles.begin() + static_cast<std::ptrdiff_t>(begin),
            triangles.begin() + static_cast<std::ptrdiff_t>(end));
        const std::vector<StaticTriangle> split = splitter.run(group);
        out.insert(out.end(), split.begin(), split.end());
        begin = end;
    }
    geometry.triangles = std::move(out);
    stats.trianglesAdded = static_cast<uint32_t>(geometry.triangles.size() - before);
    return stats;
}

std::vector<uint32_t> givenUpPrimaries(const StaticGeometry& geometry,
                                       std::span<const StaticTriangle> triangles, uint32_t own,
                                       uint32_t primaryCount,
                                       const PrimaryIlluminanceFn& illuminance) {
    std::vector<uint8_t> reaches(primaryCount, 0);
    std::vector<double> scratch(primaryCount, 0.0);
    std::vector<uint32_t> done;
    for (const StaticTriangle& t : triangles) {
        for (uint32_t id : t.v) {
            const CompileVertex& v = geometry.vertices[id];
            std::fill(scratch.begin(), scratch.end(), 0.0);
            illuminance(v.position, v.normal, scratch);
            for (uint32_t i = 0; i < primaryCount; ++i)
                if (scratch[i] > 0.0) reaches[i] = 1;
        }
    }
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < primaryCount; ++i)
        if (reaches[i] && i != own) out.push_back(i);
    return out;
}

}  // namespace onelight::world
