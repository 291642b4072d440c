#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <random>
#include <set>

#include "ecs/registry.hpp"
#include "ecs/schedule.hpp"

using namespace onelight::ecs;

namespace {
struct Position {
    float x, y, z;
};
struct Velocity {
    float x, y, z;
};
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
