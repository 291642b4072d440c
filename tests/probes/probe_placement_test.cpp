// Automatic probe placement (bake/probes/probe_placement.hpp) on small levels built in code:
// closed rooms with thick walls, a doorway between them, a solid block, the void outside a
// level's shell; lattice counts, authored probes, cameras, the empty level, determinism.
#include <gtest/gtest.h>

#include <memory>

#include <tbb/task_arena.h>

#include "bake/probes/probe_placement.hpp"
#include "bake_scenes.hpp"
#include "world/compile/static_split.hpp"
#include "world/error.hpp"

using namespace onelight;
using namespace onelight::bake;

namespace {

// An axis-aligned rectangle at coordinate `at` on `axis`, over [lo, hi] on the next two axes
// (cyclically, so that their cross product is +axis), facing +axis when sign > 0.
void face(world::SourceLevel& level, int axis, float at, glm::vec2 lo, glm::vec2 hi, float sign) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    auto corner = [&](float cu, float cv) {
        glm::vec3 p(0.0f);
        p[axis] = at;
        p[u] = cu;
        p[v] = cv;
        return p;
    };
    const glm::vec3 a = corner(lo.x, lo.y), b = corner(hi.x, lo.y), c = corner(hi.x, hi.y),
                    d = corner(lo.x, hi.y);
    if (sign > 0.0f)
        test::addQuad(level, a, b, c, d, 0, "face");
    else
        test::addQuad(level, d, c, b, a, 0, "face");
}

// The doorway of the two-room levels: y in [1, 3], z in [0, 2].
constexpr glm::vec2 kDoorLo(1.0f, 0.0f), kDoorHi(3.0f, 2.0f);

// A closed room [lo, hi], faces inward; a doorway in its -x or +x wall when asked.
void room(world::SourceLevel& level, glm::vec3 lo, glm::vec3 hi, bool doorMinusX = false,
          bool doorPlusX = false) {
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const glm::vec2 flo(lo[u], lo[v]), fhi(hi[u], hi[v]);
        for (int side = 0; side < 2; ++side) {
            const float at = side == 0 ? lo[axis] : hi[axis];
            const float sign = side == 0 ? 1.0f : -1.0f;
            const bool door = axis == 0 && (side == 0 ? doorMinusX : doorPlusX);
            if (!door) {
                face(level, axis, at, flo, fhi, sign);
                continue;
            }
            // The wall around the doorway (u = y, v = z on the x axis): both sides, the lintel.
            face(level, axis, at, flo, {kDoorLo.x, fhi.y}, sign);
            face(level, axis, at, {kDoorHi.x, flo.y}, fhi, sign);
            face(level, axis, at, {kDoorLo.x, kDoorHi.y}, {kDoorHi.x, fhi.y}, sign);
        }
    }
}

// Rooms A = [0,4] x [0,4] x [0,3] and B = [5,9] x [0,4] x [0,3]: a 1 m thick wall of solid
// between them (x in (4, 5)). With a door, a tunnel through that wall joins their doorways.
world::SourceLevel twoRooms(bool door) {
    world::SourceLevel level;
    test::addLambertMaterial(level, 0.5f);
    room(level, {0.0f, 0.0f, 0.0f}, {4.0f, 4.0f, 3.0f}, false, door);
    room(level, {5.0f, 0.0f, 0.0f}, {9.0f, 4.0f, 3.0f}, door, false);
    if (door) {
        face(level, 2, kDoorLo.y, {4.0f, kDoorLo.x}, {5.0f, kDoorHi.x}, 1.0f);   // floor
        face(level, 2, kDoorHi.y, {4.0f, kDoorLo.x}, {5.0f, kDoorHi.x}, -1.0f);  // ceiling
        face(level, 1, kDoorLo.x, {kDoorLo.y, 4.0f}, {kDoorHi.y, 5.0f}, 1.0f);   // side
        face(level, 1, kDoorHi.x, {kDoorLo.y, 4.0f}, {kDoorHi.y, 5.0f}, -1.0f);  // side
    }
    return level;
}

// The level's materials made specular (a dielectric of f0 0.04), as kFeatureProbes says.
std::vector<world::Material> specular(std::vector<world::Material> materials) {
    for (world::Material& m : materials) {
        m.materialClass = world::MaterialClass::kDielectric;
        m.specularColor = glm::vec3(0.04f);
    }
    return materials;
}

// The static world of `source` in Embree, and a compiled level with its bounds, specular
// materials (kFeatureProbes) and cameras: what placeProbes reads.
struct Built {
    explicit Built(const world::SourceLevel& source)
        : split(world::splitStaticDynamic(source)),
          scene(device, split.staticGeometry, specular(source.materials)) {
        level.settings.boundsMin = scene.boundsMin();
        level.settings.boundsMax = scene.boundsMax();
        level.features.flags = world::kFeatureProbes;
        level.cameras = source.cameras;
    }
    EmbreeDevice device;
    world::SplitLevel split;
    BakeScene scene;
    world::CompiledLevel level;
};

std::vector<ProbePlacement> place(const Built& built, float spacing,
                                  ProbePlacementStats* stats = nullptr) {
    ProbePlacementSettings settings;
    settings.spacing = spacing;
    return placeProbes(built.level, built.scene, settings, stats);
}

bool strictlyInside(glm::vec3 p, glm::vec3 lo, glm::vec3 hi) {
    return glm::all(glm::greaterThan(p, lo)) && glm::all(glm::lessThan(p, hi));
}

size_t countInside(const std::vector<ProbePlacement>& probes, glm::vec3 lo, glm::vec3 hi) {
    size_t n = 0;
    for (const ProbePlacement& p : probes) n += strictlyInside(p.position, lo, hi) ? 1 : 0;
    return n;
}

const glm::vec3 kRoomALo(0.0f), kRoomAHi(4.0f, 4.0f, 3.0f);
const glm::vec3 kRoomBLo(5.0f, 0.0f, 0.0f), kRoomBHi(9.0f, 4.0f, 3.0f);
const glm::vec3 kWallLo(4.0f, 0.0f, 0.0f), kWallHi(5.0f, 4.0f, 3.0f);

}  // namespace

TEST(ProbePlacement, ClosedRoomsEachGetProbesAndTheWallBetweenNone) {
    const Built built(twoRooms(false));
    ProbePlacementStats stats;
    const std::vector<ProbePlacement> probes = place(built, 1.0f, &stats);
    // Lattice 9 x 4 x 3 at 1 m: 48 points per room, 12 in the wall.
    EXPECT_EQ(stats.lattice, glm::uvec3(9u, 4u, 3u));
    EXPECT_EQ(stats.components, 2u);
    EXPECT_EQ(stats.openPoints, 96u);
    ASSERT_EQ(probes.size(), 96u);
    EXPECT_EQ(countInside(probes, kRoomALo, kRoomAHi), 48u);
    EXPECT_EQ(countInside(probes, kRoomBLo, kRoomBHi), 48u);
    EXPECT_EQ(countInside(probes, kWallLo, kWallHi), 0u) << "a probe inside the wall's solid";
    // By component, lowest lattice index first: room A's 48, then room B's. Each is
    // box-projected with its room's walls as the box (the rays' farthest hits land on the
    // walls: float rounding only, 1 mm).
    EXPECT_EQ(stats.boxed, 96u);
    for (size_t i = 0; i < probes.size(); ++i) {
        const bool inA = i < 48;
        EXPECT_EQ(probes[i].position.x < 4.0f, inA) << i;
        EXPECT_EQ(probes[i].entity, world::kNoIndex);
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(probes[i].boxMin[a], (inA ? kRoomALo : kRoomBLo)[a], 1e-3f) << i;
            EXPECT_NEAR(probes[i].boxMax[a], (inA ? kRoomAHi : kRoomBHi)[a], 1e-3f) << i;
        }
    }
}

// A block in the room shortens the rays that meet it, not the farthest: every probe of room A,
// those above and beside the block too, still gets the room's walls as its box.
TEST(ProbePlacement, FittedBoxesAreTheWallsNotTheObstacles) {
    world::SourceLevel source = twoRooms(false);
    test::addBox(source, {1.5f, 1.5f, 0.0f}, {2.5f, 2.5f, 1.0f}, 0, false, "block");
    const Built built(source);
    ProbePlacementStats stats;
    const std::vector<ProbePlacement> probes = place(built, 1.0f, &stats);
    size_t checked = 0;
    for (const ProbePlacement& p : probes) {
        if (!strictlyInside(p.position, kRoomALo, kRoomAHi)) continue;
        ASSERT_LT(p.boxMin.x, p.boxMax.x) << "unboxed at " << p.position.x << " " << p.position.y;
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(p.boxMin[a], kRoomALo[a], 1e-3f);
            EXPECT_NEAR(p.boxMax[a], kRoomAHi[a], 1e-3f);
        }
        ++checked;
    }
    EXPECT_GT(checked, 40u);
}

// Under the open sky most rays through the upper face escape: no box.
TEST(ProbePlacement, AnOpenYardIsNotBoxed) {
    world::SourceLevel source;
    const uint32_t m = test::addLambertMaterial(source, 0.5f);
    test::addQuad(source, {-4.0f, 0.0f, -4.0f}, {-4.0f, 0.0f, 4.0f}, {4.0f, 0.0f, 4.0f},
                  {4.0f, 0.0f, -4.0f}, m, "floor");
    test::addBox(source, {3.0f, 0.0f, 3.0f}, {3.5f, 0.2f, 3.5f}, m, false, "step");
    const Built built(source);
    ProbePlacementStats stats;
    const std::vector<ProbePlacement> probes = place(built, 4.0f, &stats);
    ASSERT_FALSE(probes.empty());
    EXPECT_EQ(stats.boxed, 0u);
    for (const ProbePlacement& p : probes) EXPECT_EQ(p.boxMax, glm::vec3(0.0f));
}

TEST(ProbePlacement, ADoorwayMergesTheRoomsIntoOneComponent) {
    const Built built(twoRooms(true));
    ProbePlacementStats stats;
    const std::vector<ProbePlacement> probes = place(built, 1.0f, &stats);
    EXPECT_EQ(stats.components, 1u);
    // Both rooms plus the four points inside the tunnel (x 4.5, y 1.5 / 2.5, z 0.5 / 1.5).
    EXPECT_EQ(probes.size(), 100u);
    EXPECT_EQ(countInside(probes, kWallLo, kWallHi), 4u);
    const glm::vec3 tunnelLo(4.0f, kDoorLo.x, kDoorLo.y), tunnelHi(5.0f, kDoorHi.x, kDoorHi.y);
    EXPECT_EQ(countInside(probes, tunnelLo, tunnelHi), 4u) << "wall probes outside the tunnel";
}

TEST(ProbePlacement, AThinPartitionSplitsARoomUnlessItHasADoor) {
    // One room [0,8] x [0,4] x [0,3] split at x = 4 by a wall of no thickness (two quads back
    // to back): the lattice points on either side (x 3.5 and 4.5) are both open, and only the
    // occlusion of the segment between them tells the halves apart.
    for (bool door : {false, true}) {
        world::SourceLevel source;
        const uint32_t m = test::addLambertMaterial(source, 0.5f);
        test::addBox(source, glm::vec3(0.0f), {8.0f, 4.0f, 3.0f}, m, true, "room");
        for (float sign : {-1.0f, 1.0f}) {
            if (!door) {
                face(source, 0, 4.0f, glm::vec2(0.0f), {4.0f, 3.0f}, sign);
                continue;
            }
            face(source, 0, 4.0f, glm::vec2(0.0f), {kDoorLo.x, 3.0f}, sign);
            face(source, 0, 4.0f, {kDoorHi.x, 0.0f}, {4.0f, 3.0f}, sign);
            face(source, 0, 4.0f, {kDoorLo.x, kDoorHi.y}, {kDoorHi.x, 3.0f}, sign);
        }
        const Built built(source);
        ProbePlacementStats stats;
        EXPECT_EQ(place(built, 1.0f, &stats).size(), 96u) << door;
        EXPECT_EQ(stats.components, door ? 1u : 2u) << door;
    }
}

TEST(ProbePlacement, NoProbeInsideASolidBlock) {
    world::SourceLevel source;
    const uint32_t m = test::addLambertMaterial(source, 0.5f);
    test::addBox(source, glm::vec3(0.0f), glm::vec3(8.0f), m, true, "room");
    test::addBox(source, glm::vec3(2.0f), glm::vec3(6.0f), m, false, "block");
    const Built built(source);
    ProbePlacementStats stats;
    const std::vector<ProbePlacement> probes = place(built, 2.0f, &stats);
    EXPECT_EQ(countInside(probes, glm::vec3(2.0f), glm::vec3(6.0f)), 0u);
    EXPECT_EQ(probes.size(), 64u - 8u);  // 4^3 points (1, 3, 5, 7 per axis), 2^3 in the block
    EXPECT_EQ(stats.components, 1u);
}

TEST(ProbePlacement, HalvingTheSpacingGivesEightTimesTheProbes) {
    world::SourceLevel source;
    test::addBox(source, glm::vec3(0.0f), glm::vec3(8.0f), test::addLambertMaterial(source, 0.5f),
                 true, "room");
    const Built built(source);
    ProbePlacementStats coarse, fine;
    EXPECT_EQ(place(built, 4.0f, &coarse).size(), 8u);
    EXPECT_EQ(place(built, 2.0f, &fine).size(), 64u);
    EXPECT_EQ(coarse.components, 1u);
    EXPECT_EQ(fine.components, 1u);
    EXPECT_FLOAT_EQ(fine.spacing, 2.0f);
}

TEST(ProbePlacement, TheLevelsSpacingWinsOverTheBakeDefault) {
    world::SourceLevel source;
    test::addBox(source, glm::vec3(0.0f), glm::vec3(8.0f), test::addLambertMaterial(source, 0.5f),
                 true, "room");
    Built built(source);
    built.level.settings.probeSpacing = 2.0f;
    EXPECT_EQ(place(built, 1.0f).size(), 64u);
}

TEST(ProbePlacement, TheLatticeIsCappedByGrowingTheSpacing) {
    world::SourceLevel source;
    test::addBox(source, glm::vec3(0.0f), glm::vec3(8.0f), test::addLambertMaterial(source, 0.5f),
                 true, "room");
    const Built built(source);
    ProbePlacementStats stats;
    const std::vector<ProbePlacement> probes = place(built, 0.1f, &stats);  // 80^3 requested
    EXPECT_LE(stats.latticePoints, kMaxProbeLatticePoints);
    EXPECT_GE(stats.latticePoints, kMaxProbeLatticePoints / 2);
    EXPECT_GT(stats.spacing, 0.1f);
    EXPECT_EQ(probes.size(), stats.latticePoints);
}

TEST(ProbePlacement, TheVoidOutsideClosedRoomsGetsNoProbe) {
    // An L of three closed rooms with 1 m walls; the bounds' corner [5,9] x [5,9] is outside
    // them all, where rays escape or hit the outside of walls.
    world::SourceLevel source;
    test::addLambertMaterial(source, 0.5f);
    room(source, {0.0f, 0.0f, 0.0f}, {4.0f, 4.0f, 3.0f});
    room(source, {5.0f, 0.0f, 0.0f}, {9.0f, 4.0f, 3.0f});
    room(source, {0.0f, 5.0f, 0.0f}, {4.0f, 9.0f, 3.0f});
    const Built built(source);
    ProbePlacementStats stats;
    const std::vector<ProbePlacement> probes = place(built, 1.0f, &stats);
    EXPECT_EQ(countInside(probes, {5.0f, 5.0f, 0.0f}, {9.0f, 9.0f, 3.0f}), 0u);
    EXPECT_EQ(probes.size(), 3u * 48u);
    EXPECT_EQ(stats.components, 3u);
}

TEST(ProbePlacement, CamerasAddAProbeWhenFarFromOthersAndNotInSolid) {
    world::SourceLevel source;
    const uint32_t m = test::addLambertMaterial(source, 0.5f);
    test::addBox(source, glm::vec3(0.0f), glm::vec3(8.0f), m, true, "room");
    test::addBox(source, {3.5f, 3.5f, 0.2f}, {4.5f, 4.5f, 1.0f}, m, false, "block");
    world::Camera camera;
    for (glm::vec3 at : {glm::vec3(4.0f, 4.0f, 4.0f),     // 3.5 m from the lattice: kept
                         glm::vec3(2.5f, 2.0f, 2.0f),     // 0.5 m from (2, 2, 2): dropped
                         glm::vec3(4.1f, 4.0f, 4.0f),     // 0.1 m from the first camera's
                         glm::vec3(4.0f, 4.0f, 0.6f)}) {  // inside the block: dropped
        camera.position = at;
        source.cameras.push_back(camera);
    }
    const Built built(source);
    ProbePlacementStats stats;
    const std::vector<ProbePlacement> probes = place(built, 4.0f, &stats);  // points at 2 and 6
    ASSERT_EQ(probes.size(), 9u);
    EXPECT_EQ(stats.cameraProbes, 1u);
    EXPECT_EQ(probes.back().position, glm::vec3(4.0f));
    EXPECT_EQ(probes.back().entity, world::kNoIndex);
}

// An authored probe inside a solid block is kept (the author asked for it) but flagged, so
// that the bake can warn; one in the open is not.
TEST(ProbePlacement, AuthoredProbesInsideSolidAreFlagged) {
    world::SourceLevel source;
    const uint32_t m = test::addLambertMaterial(source, 0.5f);
    test::addBox(source, glm::vec3(0.0f), glm::vec3(8.0f), m, true, "room");
    test::addBox(source, glm::vec3(2.0f), glm::vec3(4.0f), m, false, "block");
    Built built(source);
    world::Entity e;
    e.flags = world::kEntityProbe;
    e.position = glm::vec3(3.0f);  // in the block
    built.level.entities.push_back(e);
    e.position = glm::vec3(6.0f);  // in the open
    built.level.entities.push_back(e);
    const std::vector<ProbePlacement> probes = place(built, 2.0f);
    ASSERT_EQ(probes.size(), 2u);
    EXPECT_TRUE(probes[0].insideSolid);
    EXPECT_FALSE(probes[1].insideSolid);
}

TEST(ProbePlacement, AuthoredProbesWin) {
    Built built(twoRooms(true));
    world::Entity e;
    e.flags = world::kEntityDynamic;
    built.level.entities.push_back(e);
    e.flags = world::kEntityProbe;
    e.position = glm::vec3(2.0f, 2.0f, 1.5f);
    e.probeBoxMin = glm::vec3(0.0f);
    e.probeBoxMax = glm::vec3(4.0f, 4.0f, 3.0f);
    built.level.entities.push_back(e);
    e.position = glm::vec3(7.0f, 2.0f, 1.5f);
    e.probeBoxMin = e.probeBoxMax = glm::vec3(0.0f);  // empty: no box
    built.level.entities.push_back(e);
    const std::vector<ProbePlacement> probes = place(built, 1.0f);
    ASSERT_EQ(probes.size(), 2u);
    EXPECT_EQ(probes[0].entity, 1u);
    EXPECT_EQ(probes[0].position, glm::vec3(2.0f, 2.0f, 1.5f));
    EXPECT_EQ(probes[0].boxMax, glm::vec3(4.0f, 4.0f, 3.0f));
    EXPECT_EQ(probes[1].entity, 2u);
    EXPECT_EQ(probes[1].boxMax, glm::vec3(0.0f));
}

TEST(ProbePlacement, NoneWithoutSpecularMaterials) {
    Built built(twoRooms(true));
    built.level.features.flags = 0;
    EXPECT_TRUE(place(built, 1.0f).empty());
}

// A glossy floor alone reflects nothing but the sky: no probe (the runtime's probe-less path
// gives a uniform sky exactly; a sunlit quad used to get a lattice of them), unless the sky is
// an image.
TEST(ProbePlacement, AnOpenFloorUnderAUniformSkyGetsNoProbe) {
    world::SourceLevel source;
    test::addQuad(source, {-4.0f, 0.0f, -4.0f}, {-4.0f, 0.0f, 4.0f}, {4.0f, 0.0f, 4.0f},
                  {4.0f, 0.0f, -4.0f}, test::addLambertMaterial(source, 0.5f), "floor");
    Built built(source);
    ProbePlacementStats stats;
    EXPECT_TRUE(place(built, 4.0f, &stats).empty());
    EXPECT_TRUE(stats.nothingToReflect);
    built.level.settings.skyImage = 0;
    EXPECT_EQ(place(built, 4.0f, &stats).size(), 4u);
    EXPECT_FALSE(stats.nothingToReflect);
}

// A nearly flat level (a floor and a 20 cm step, which the floor reflects): the lattice is
// lifted to kProbeMinLatticeHeight, so its probes float half of it above the floor (they would
// otherwise lie in the floor, half their view black).
TEST(ProbePlacement, AFlatLevelsProbesFloatAboveIt) {
    world::SourceLevel source;
    const uint32_t m = test::addLambertMaterial(source, 0.5f);
    test::addQuad(source, {-4.0f, 0.0f, -4.0f}, {-4.0f, 0.0f, 4.0f}, {4.0f, 0.0f, 4.0f},
                  {4.0f, 0.0f, -4.0f}, m, "floor");
    test::addBox(source, {3.0f, 0.0f, 3.0f}, {3.5f, 0.2f, 3.5f}, m, false, "step");
    const Built built(source);
    const std::vector<ProbePlacement> probes = place(built, 4.0f);
    ASSERT_EQ(probes.size(), 4u);  // 2 x 1 x 2
    for (const ProbePlacement& p : probes)
        EXPECT_FLOAT_EQ(p.position.y, 0.5f * kProbeMinLatticeHeight);
}

TEST(ProbePlacement, AnEmptyLevelGetsOneProbeAtTheCentre) {
    EmbreeDevice device;
    const BakeScene scene(device, world::StaticGeometry{}, std::vector<world::Material>{});
    world::CompiledLevel level;
    level.settings.boundsMin = glm::vec3(-2.0f);
    level.settings.boundsMax = glm::vec3(4.0f);
    level.features.flags = world::kFeatureProbes;
    world::Camera camera;
    camera.position = glm::vec3(3.0f);
    level.cameras.push_back(camera);
    const std::vector<ProbePlacement> probes = placeProbes(level, scene, {});
    ASSERT_EQ(probes.size(), 1u);
    EXPECT_EQ(probes[0].position, glm::vec3(1.0f));
    EXPECT_EQ(probes[0].entity, world::kNoIndex);
}

TEST(ProbePlacement, SameResultTwiceAndOnOneThread) {
    const Built built(twoRooms(true));
    ProbePlacementStats first, second, single;
    const std::vector<ProbePlacement> a = place(built, 0.5f, &first);
    const std::vector<ProbePlacement> b = place(built, 0.5f, &second);
    std::vector<ProbePlacement> c;
    tbb::task_arena(1).execute([&] { c = place(built, 0.5f, &single); });
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a.size(), c.size());
    for (size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a[i].position, b[i].position) << i;
        ASSERT_EQ(a[i].position, c[i].position) << i;
    }
    EXPECT_EQ(first.components, second.components);
    EXPECT_EQ(first.rays.total(), single.rays.total());
}

TEST(ProbePlacement, MoreProbesThanTheRuntimeHoldsAreRefusedBeforeCapture) {
    EXPECT_NO_THROW(checkProbeBudget(kMaxBakedProbes, 128));
    try {
        checkProbeBudget(kMaxBakedProbes + 1, 64);
        FAIL() << "342 probes accepted";
    } catch (const world::Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("342 environment probes"), std::string::npos) << message;
        EXPECT_NE(message.find("at most 341"), std::string::npos) << message;
        // 342 cubes of 64 with their mips: 342 * 32766 texels of 4 bytes = 45 MB.
        EXPECT_NE(message.find("(45 MB"), std::string::npos) << message;
    }
}
