#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "ecs/registry.hpp"
#include "ecs/schedule.hpp"
#include "ecs_fixtures.hpp"

using namespace onelight::ecs;
using namespace onelight::ecs::fixtures;

namespace {
struct Tag {
    int value;
};
}  // namespace

TEST(Ecs, DestroyedSlotIsReusedWithANewGeneration) {
    Registry r;
    Entity a = r.create();
    r.destroy(a);
    Entity b = r.create();
    EXPECT_EQ(indexOf(a), indexOf(b));
    EXPECT_EQ(generationOf(b), generationOf(a) + 1);
    EXPECT_FALSE(r.valid(a));
    EXPECT_TRUE(r.valid(b));
    EXPECT_EQ(r.alive(), 1u);
}

TEST(Ecs, StaleHandleSeesNothingOfTheNewEntity) {
    Registry r;
    Entity a = r.create();
    r.emplace<Tag>(a, 1);
    r.destroy(a);
    Entity b = r.create();
    r.emplace<Tag>(b, 2);
    EXPECT_EQ(r.tryGet<Tag>(a), nullptr);
    EXPECT_FALSE(r.allOf<Tag>(a));
    EXPECT_EQ(r.get<Tag>(b).value, 2);
}

TEST(Ecs, GenerationWrapsAfterItsBits) {
    Registry r;
    Entity first = r.create();
    Entity e = first;
    for (uint32_t i = 0; i <= kGenerationMask; ++i) {
        r.destroy(e);
        e = r.create();
    }
    EXPECT_EQ(indexOf(e), indexOf(first));
    EXPECT_EQ(generationOf(e), generationOf(first));  // 1024 reuses later the handle repeats
}

TEST(Ecs, ViewVisitsExactlyTheEntitiesWithAllComponents) {
    Registry r;
    std::set<uint32_t> both;
    for (int i = 0; i < 1000; ++i) {
        Entity e = r.create();
        if (i % 2 == 0) r.emplace<Position>(e, float(i), 0.f, 0.f);
        if (i % 3 == 0) r.emplace<Velocity>(e, 1.f, 0.f, 0.f);
        if (i % 6 == 0) both.insert(uint32_t(e));
    }
    std::set<uint32_t> seen;
    for (auto [e, p, v] : r.view<Position, Velocity>().each()) {
        EXPECT_TRUE(seen.insert(uint32_t(e)).second) << "visited twice";
        EXPECT_EQ(p.x, float(indexOf(e)));
        p.x += v.x;  // writes go to the pool
    }
    EXPECT_EQ(seen, both);
    for (uint32_t e : both) EXPECT_EQ(r.get<Position>(Entity{e}).x, float(indexOf(Entity{e})) + 1);
}

// A long random sequence of creates, destroys, emplaces and removes, mirrored in a plain map.
TEST(Ecs, RandomOperationsMatchAPlainModel) {
    Registry r;
    struct Model {
        std::optional<int> tag;
        std::optional<float> px;
    };
    std::map<uint32_t, Model> model;
    std::vector<Entity> live;
    std::mt19937 rng(7);
    for (int step = 0; step < 100000; ++step) {
        int op = int(rng() % 6);
        if (op == 0 || live.empty()) {
            Entity e = r.create();
            ASSERT_EQ(model.count(uint32_t(e)), 0u);
            model[uint32_t(e)] = {};
            live.push_back(e);
            continue;
        }
        size_t k = rng() % live.size();
        Entity e = live[k];
        Model& m = model[uint32_t(e)];
        switch (op) {
            case 1:
                r.destroy(e);
                model.erase(uint32_t(e));
                live[k] = live.back();
                live.pop_back();
                break;
            case 2:
                if (!m.tag) r.emplace<Tag>(e, step), m.tag = step;
                break;
            case 3:
                if (m.tag) r.remove<Tag>(e), m.tag.reset();
                break;
            case 4:
                if (!m.px) r.emplace<Position>(e, float(step), 0.f, 0.f), m.px = float(step);
                break;
            default:
                if (m.px) r.remove<Position>(e), m.px.reset();
                break;
        }
    }
    ASSERT_EQ(r.alive(), model.size());
    size_t withBoth = 0;
    for (auto& [id, m] : model) {
        Entity e{id};
        ASSERT_TRUE(r.valid(e));
        ASSERT_EQ(r.tryGet<Tag>(e) != nullptr, m.tag.has_value());
        if (m.tag) {
            ASSERT_EQ(r.get<Tag>(e).value, *m.tag);
        }
        if (m.px) {
            ASSERT_EQ(r.get<Position>(e).x, *m.px);
        }
        withBoth += m.tag && m.px;
    }
    size_t viewed = 0;
    r.view<Tag, Position>().forEach([&](Entity, Tag&, Position&) { ++viewed; });
    EXPECT_EQ(viewed, withBoth);
}

TEST(Ecs, EqualHistoriesIterateInTheSameOrder) {
    auto build = []() {
        Registry r;
        std::mt19937 rng(3);
        std::vector<Entity> es;
        for (int i = 0; i < 500; ++i) es.push_back(r.create());
        for (Entity e : es)
            if (rng() % 2) r.emplace<Tag>(e, int(indexOf(e)));
        for (int i = 0; i < 100; ++i) r.destroy(es[rng() % 5 * 100 + i]);
        std::vector<uint32_t> order;
        for (auto [e, t] : r.view<Tag>().each()) order.push_back(uint32_t(e) + uint32_t(t.value));
        return order;
    };
    EXPECT_EQ(build(), build());
}

// Reads (views, get, tryGet, allOf) never create a pool, on a const or a non-const registry.
TEST(Ecs, ReadsCreateNoPools) {
    Registry r;
    Entity e = r.create();
    r.emplace<Position>(e, 1.f, 2.f, 3.f);
    ASSERT_EQ(r.poolCount(), 1u);
    const Registry& c = r;
    EXPECT_FALSE(c.allOf<Velocity>(e));
    EXPECT_FALSE((c.allOf<Position, Velocity>(e)));
    EXPECT_TRUE(c.allOf<Position>(e));
    EXPECT_EQ(c.tryGet<Velocity>(e), nullptr);
    EXPECT_EQ(c.get<Position>(e).y, 2.f);
    EXPECT_EQ(r.tryGet<Velocity>(e), nullptr);
    EXPECT_FALSE(r.allOf<Tag>(e));
    size_t visited = 0;
    for ([[maybe_unused]] auto [x, p, v] : c.view<Position, Velocity>().each()) ++visited;
    for ([[maybe_unused]] auto [x, p, v] : r.view<Position, Velocity>().each()) ++visited;
    for ([[maybe_unused]] auto [x, t] : r.view<const Tag>().each()) ++visited;
    c.view<Velocity>().forEach([&](Entity, const Velocity&) { ++visited; });
    r.view<Velocity, Position>().forEach([&](Entity, Velocity&, Position&) { ++visited; });
    EXPECT_EQ(visited, 0u);
    EXPECT_EQ(r.poolCount(), 1u);
    EXPECT_TRUE(r.hasPool<Position>());
    EXPECT_FALSE(r.hasPool<Velocity>());
    EXPECT_FALSE(r.hasPool<Tag>());
    EXPECT_EQ(c.findPool<Velocity>(), nullptr);
    r.emplace<Velocity>(e, 0.f, 0.f, 0.f);  // emplace is what creates a pool
    EXPECT_EQ(r.poolCount(), 2u);
    EXPECT_TRUE((c.allOf<Position, Velocity>(e)));
}

TEST(Ecs, ConstViewYieldsConstComponentsOfTheRightEntities) {
    Registry r;
    std::map<uint32_t, float> expected;  // entity -> Position::x of those with a Tag too
    for (int i = 0; i < 300; ++i) {
        Entity e = r.create();
        if (i % 2 == 0) r.emplace<Position>(e, float(i), 0.f, 0.f);
        if (i % 5 == 0) r.emplace<Tag>(e, i);
        if (i % 10 == 0) expected[uint32_t(e)] = float(i);
    }
    const Registry& c = r;
    auto view = c.view<Position, Tag>();
    static_assert(std::is_same_v<decltype(view), View<const Position, const Tag>>);
    using Item = decltype(*view.each().begin());
    static_assert(std::is_same_v<std::tuple_element_t<1, Item>, const Position&>);
    static_assert(std::is_same_v<std::tuple_element_t<2, Item>, const Tag&>);
    std::map<uint32_t, float> seen;
    for (auto [e, p, t] : view.each()) {
        EXPECT_TRUE(seen.emplace(uint32_t(e), p.x).second) << "visited twice";
        EXPECT_EQ(float(t.value), p.x);
    }
    EXPECT_EQ(seen, expected);
    std::map<uint32_t, float> forEachSeen;
    view.forEach([&](Entity e, const Position& p, const Tag&) { forEachSeen[uint32_t(e)] = p.x; });
    EXPECT_EQ(forEachSeen, expected);
}

TEST(Ecs, ConstViewOverAnAbsentComponentIsEmpty) {
    const Registry empty;
    EXPECT_FALSE(empty.view<Position>().each().begin() != empty.view<Position>().each().end());
    Registry r;
    for (int i = 0; i < 10; ++i) r.emplace<Position>(r.create(), float(i), 0.f, 0.f);
    const Registry& c = r;
    size_t visited = 0;
    for ([[maybe_unused]] auto [e, v] : c.view<Velocity>().each()) ++visited;
    for ([[maybe_unused]] auto [e, p, v] : c.view<Position, Velocity>().each()) ++visited;
    for ([[maybe_unused]] auto [e, v, p] : c.view<Velocity, Position>().each()) ++visited;
    c.view<Position, Velocity>().forEach(
        [&](Entity, const Position&, const Velocity&) { ++visited; });
    EXPECT_EQ(visited, 0u);
    for ([[maybe_unused]] auto [e, p] : c.view<Position>().each()) ++visited;
    EXPECT_EQ(visited, 10u);
    EXPECT_EQ(r.poolCount(), 1u);
}

TEST(Ecs, ViewOverAPoolEmptiedByRemovalsIsEmpty) {
    Registry r;
    Entity e = r.create();
    r.emplace<Position>(e, 0.f, 0.f, 0.f);
    r.emplace<Velocity>(e, 0.f, 0.f, 0.f);
    r.remove<Velocity>(e);
    size_t visited = 0;
    for ([[maybe_unused]] auto [x, p, v] : r.view<Position, Velocity>().each()) ++visited;
    EXPECT_EQ(visited, 0u);
}

namespace {
// What an entity has, kept beside the registry by RandomHistory.
struct Reference {
    std::optional<Position> p;
    std::optional<Velocity> v;
    std::optional<int> tag;
};

// A seeded random history of creates, destroys, emplaces and removes of Position, Velocity and
// Tag, with updates through the group<Position, Velocity> (made at step groupAt), mirrored in a
// plain map.
class RandomHistory {
public:
    RandomHistory(uint32_t seed, int groupAt) : rng_(seed), groupAt_(groupAt) {}

    // Runs steps [from, to).
    void run(int from, int to) {
        for (int step = from; step < to; ++step) {
            if (step == groupAt_) group_ = r_.group<Position, Velocity>();
            one(step);
        }
    }

    // The group and the views agree with the plain map; values too.
    void check() {
        ASSERT_TRUE(group_.has_value());
        const Group<Position, Velocity>& g = *group_;
        std::set<uint32_t> expected;
        for (auto& [id, m] : model_)
            if (m.p && m.v) expected.insert(id);
        ASSERT_EQ(g.size(), expected.size());
        std::vector<uint32_t> order;
        for (auto [e, p, v] : g.each()) {
            order.push_back(uint32_t(e));
            const Reference& m = model_.at(uint32_t(e));
            ASSERT_TRUE(m.p && m.v) << "grouped without both components";
            EXPECT_EQ(p.x, m.p->x);
            EXPECT_EQ(p.y, m.p->y);
            EXPECT_EQ(v.x, m.v->x);
            EXPECT_EQ(v.z, m.v->z);
            EXPECT_EQ(&p, &r_.get<Position>(e));
            EXPECT_EQ(&v, &r_.get<Velocity>(e));
        }
        EXPECT_EQ(std::set<uint32_t>(order.begin(), order.end()), expected);
        EXPECT_EQ(order.size(), expected.size()) << "visited twice";
        std::vector<uint32_t> forEachOrder;
        g.forEach([&](Entity e, Position&, Velocity&) { forEachOrder.push_back(uint32_t(e)); });
        EXPECT_EQ(forEachOrder, order);
        // The prefix: the first size() slots of both pools hold the group, in the same order.
        const ComponentPool<Position>& ps = r_.pool<Position>();
        const ComponentPool<Velocity>& vs = r_.pool<Velocity>();
        for (size_t i = 0; i < g.size(); ++i) {
            ASSERT_EQ(ps.entities()[i], vs.entities()[i]) << "slot " << i;
            ASSERT_EQ(uint32_t(g.entities()[i]), order[i]);
        }
        for (auto& [id, m] : model_) EXPECT_EQ(g.contains(Entity{id}), m.p && m.v);
        std::set<uint32_t> viewed;
        for (auto [e, p, v] : r_.view<Position, Velocity>().each()) {
            viewed.insert(uint32_t(e));
            EXPECT_EQ(p.x, model_.at(uint32_t(e)).p->x);
        }
        EXPECT_EQ(viewed, expected);
        std::set<uint32_t> tagged;
        for (auto [e, t] : std::as_const(r_).view<Tag>().each()) {
            tagged.insert(uint32_t(e));
            EXPECT_EQ(t.value, *model_.at(uint32_t(e)).tag);
        }
        size_t expectedTagged = 0;
        for (auto& [id, m] : model_) expectedTagged += m.tag.has_value();
        EXPECT_EQ(tagged.size(), expectedTagged);
    }

    // (entity, Position::x, Velocity::x) in group order, then entities in view order.
    std::vector<float> iteration() const {
        std::vector<float> out;
        for (auto [e, p, v] : group_->each()) out.insert(out.end(), {float(uint32_t(e)), p.x, v.x});
        for (auto [e, p, t] : r_.view<Position, Tag>().each())
            out.insert(out.end(), {float(uint32_t(e)), p.x, float(t.value)});
        return out;
    }

    Registry& registry() { return r_; }

private:
    void one(int step) {
        int op = int(rng_() % 11);
        if (op == 0 || op == 10 || live_.empty()) {  // creates outnumber destroys: it grows
            Entity e = r_.create();
            model_[uint32_t(e)] = {};
            live_.push_back(e);
            return;
        }
        size_t k = rng_() % live_.size();
        Entity e = live_[k];
        Reference& m = model_[uint32_t(e)];
        float f = float(step);
        switch (op) {
            case 1:
                r_.destroy(e);
                model_.erase(uint32_t(e));
                live_[k] = live_.back();
                live_.pop_back();
                break;
            case 2:
            case 3:
                if (!m.p) m.p = r_.emplace<Position>(e, f, float(indexOf(e)), 0.f);
                break;
            case 4:
                if (m.p) r_.remove<Position>(e), m.p.reset();
                break;
            case 5:
            case 6:
                if (!m.v) m.v = r_.emplace<Velocity>(e, 1.f, 0.f, f);
                break;
            case 7:
                if (m.v) r_.remove<Velocity>(e), m.v.reset();
                break;
            case 8:
                if (m.tag) {
                    r_.remove<Tag>(e), m.tag.reset();
                } else {
                    r_.emplace<Tag>(e, step), m.tag = step;
                }
                break;
            default:  // an update through the group, mirrored in the model
                if (group_) {
                    group_->forEach([](Entity, Position& p, Velocity& v) { p.x += v.x; });
                    for (auto& [id, ref] : model_)
                        if (ref.p && ref.v) ref.p->x += ref.v->x;
                }
                break;
        }
    }

    Registry r_;
    std::mt19937 rng_;
    int groupAt_;
    std::optional<Group<Position, Velocity>> group_;
    std::map<uint32_t, Reference> model_;
    std::vector<Entity> live_;
};
}  // namespace

// The group holds exactly the entities with both components, whether it was made before,
// during or after the history.
TEST(Ecs, GroupMatchesABruteForceReferenceAfterRandomHistories) {
    for (uint32_t seed : {1u, 2u, 3u}) {
        for (int groupAt : {0, 2500, 5000}) {
            SCOPED_TRACE("seed " + std::to_string(seed) + ", group at " + std::to_string(groupAt));
            RandomHistory h(seed, groupAt);
            h.run(0, 5000);
            h.run(5000, 5001);  // makes the group if it is made at the end
            ASSERT_NO_FATAL_FAILURE(h.check());
            for (int chunk = 0; chunk < 4; ++chunk) {
                h.run(5001 + chunk * 1000, 6001 + chunk * 1000);
                ASSERT_NO_FATAL_FAILURE(h.check());
            }
            EXPECT_GT((h.registry().group<Position, Velocity>().size()), 100u);
        }
    }
}

TEST(Ecs, EqualHistoriesIterateGroupsAndViewsInTheSameOrder) {
    auto iterate = [](uint32_t seed) {
        RandomHistory h(seed, 1000);
        h.run(0, 8000);
        return h.iteration();
    };
    std::vector<float> a = iterate(11);
    EXPECT_GT(a.size(), 30u);
    EXPECT_EQ(a, iterate(11));
    EXPECT_NE(a, iterate(12));  // the comparison sees the history
}

TEST(Ecs, EmplaceReturnsTheStoredComponentWhenTheGroupMovesIt) {
    Registry r;
    auto g = r.group<Position, Velocity>();
    Entity loner = r.create();
    r.emplace<Position>(loner, -1.f, 0.f, 0.f);  // slot 0 of Position, not grouped
    Entity e = r.create();
    r.emplace<Velocity>(e, 2.f, 0.f, 0.f);
    Position& p = r.emplace<Position>(e, 7.f, 0.f, 0.f);  // lands in slot 1, moved to slot 0
    EXPECT_EQ(&p, &r.get<Position>(e));
    EXPECT_EQ(p.x, 7.f);
    EXPECT_EQ(r.get<Position>(loner).x, -1.f);
    ASSERT_EQ(g.size(), 1u);
    EXPECT_EQ(g.entities()[0], e);
    EXPECT_FALSE(g.contains(loner));
}

TEST(Ecs, GroupUpdatesTheWorldLikeAView) {
    Registry grouped = makeWorld(1000);
    Registry viewed = makeWorld(1000);
    auto g = grouped.group<Position, Velocity>();
    EXPECT_EQ(g.size(), 1000u);
    EXPECT_EQ((grouped.group<Position, Velocity>().size()), 1000u);  // the same group again
    for (int tick = 0; tick < 3; ++tick) {
        g.forEach([](Entity, Position& p, const Velocity& v) { integrate(p, v); });
        viewed.view<Position, const Velocity>().forEach(
            [](Entity, Position& p, const Velocity& v) { integrate(p, v); });
    }
    size_t compared = 0;
    for (auto [e, p] : std::as_const(viewed).view<Position>().each()) {
        EXPECT_EQ(grouped.get<Position>(e).x, p.x);
        EXPECT_EQ(grouped.get<Position>(e).z, p.z);
        ++compared;
    }
    EXPECT_EQ(compared, 1000u);
}

TEST(Ecs, GroupSurvivesMovingTheRegistry) {
    Registry a = makeWorld(10);
    auto g = a.group<Position, Velocity>();
    Registry b = std::move(a);
    Entity e = b.create();
    b.emplace<Position>(e, 0.f, 0.f, 0.f);
    b.emplace<Velocity>(e, 0.f, 0.f, 0.f);
    EXPECT_EQ(g.size(), 11u);
    EXPECT_EQ((b.group<Position, Velocity>().size()), 11u);
    b.destroy(e);
    EXPECT_EQ(g.size(), 10u);
}

TEST(EcsDeathTest, APoolIsOwnedByOneGroupAtMost) {
    Registry r;
    r.group<Position, Velocity>();
    EXPECT_DEATH((r.group<Position, Tag>()), "");
    EXPECT_DEATH((r.group<Velocity, Position>()), "");
}

TEST(Ecs, ScheduleRunsSystemsInOrderOnEveryTick) {
    Registry r;
    Schedule s;
    std::vector<std::string> calls;
    s.add("input",
          [&](Registry&, const Tick& t) { calls.push_back("input" + std::to_string(t.index)); });
    s.add("physics",
          [&](Registry&, const Tick& t) { calls.push_back("physics" + std::to_string(t.index)); });
    FixedClock clock;
    int due = clock.advance(2.5 / 60.0);
    EXPECT_EQ(due, 2);
    for (int i = 0; i < due; ++i) s.runTick(r, clock.take());
    EXPECT_EQ(calls, (std::vector<std::string>{"input0", "physics0", "input1", "physics1"}));
    EXPECT_EQ(clock.advance(0.6 / 60.0), 1);  // the leftover half tick carried over
    EXPECT_EQ(clock.advance(10.0), 8);        // a long stall runs at most 8 ticks
    EXPECT_EQ(clock.advance(0.5 / 60.0), 0);  // and the backlog is dropped
}
