// Owning groups (EnTT's basic_group with owned types only): a group over component types Ts
// owns their pools and keeps them sorted so that the first size() dense slots of every owned
// pool hold the entities that have all of Ts, in the same order. Iterating the group is then a
// plain loop over the dense arrays, with no lookup at all.
//
// Rules:
// - A pool is owned by one group at most: Registry::group<A, B>() and group<B, C>() cannot both
//   exist, nor group<B, A>() beside group<A, B>() (ask with the same type order).
// - The group is maintained on every emplace, remove and destroy: an entity that gains its last
//   owned component is swapped to the end of the prefix; one that loses any is swapped out of
//   it before the pool removes it.
// - Iteration order is the prefix order, fixed by the history of structural changes (and by
//   the pools' order when the group was made), so equal histories iterate equally.
// - Structural changes (create, destroy, emplace, remove) on the owned pools are not allowed
//   while iterating the group, as for views; collect the entities first.
#pragma once

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <span>
#include <tuple>
#include <type_traits>
#include <utility>

#include "sparse_set.hpp"

namespace onelight::ecs {

// Whether the types are pairwise distinct.
template <class... Ts>
inline constexpr bool kDistinctTypes = true;
template <class T, class... Ts>
inline constexpr bool kDistinctTypes<T, Ts...> =
    (!std::is_same_v<T, Ts> && ...) && kDistinctTypes<Ts...>;

// The state of an owning group, held by the registry and told of changes by the owned pools.
template <class... Ts>
class GroupData final : public PoolOwner {
    static_assert(sizeof...(Ts) > 0, "GroupData: a group owns at least one component type");
    static_assert(kDistinctTypes<Ts...>, "GroupData: a component type is owned twice");
    static_assert((!std::is_const_v<Ts> && ...), "GroupData: owned types are not const");

public:
    // Takes ownership of the (unowned) pools and packs the entities that have all of Ts at
    // their front, in the dense order of the first pool.
    explicit GroupData(ComponentPool<Ts>&... pools) : pools_(&pools...) {
        ((assert(!pools.owner_ && "GroupData: the pool is owned by another group"),
          pools.owner_ = this),
         ...);
        const ComponentPool<First>& first = *std::get<0>(pools_);
        for (size_t i = 0; i < first.size(); ++i) {
            Entity e = first.entities()[i];
            if (hasAll(e)) pushBack(e);
        }
    }
    // The owned pools point at this state: it neither copies nor moves.
    GroupData(const GroupData&) = delete;
    GroupData& operator=(const GroupData&) = delete;

    // An entity that now has all of Ts joins the end of the prefix.
    void afterEmplace(Entity e) override {
        if (!hasAll(e)) return;
        assert(std::get<0>(pools_)->slotOf(e) >= size_ && "GroupData: entity already grouped");
        pushBack(e);
    }

    // A grouped entity about to lose a component swaps with the last of the prefix, which
    // shrinks by one.
    void beforeRemove(Entity e) override {
        uint32_t slot = std::get<0>(pools_)->slotOf(e);
        if (slot == kNoSlot || slot >= size_) return;
        --size_;  // within the prefix the entity has this slot in every owned pool
        std::apply([&](auto*... pool) { (pool->swapSlots(slot, uint32_t(size_)), ...); }, pools_);
    }

    // Number of entities that have all of Ts (the length of the prefix).
    size_t size() const { return size_; }
    // The owned pools, in the order of Ts.
    const std::tuple<ComponentPool<Ts>*...>& pools() const { return pools_; }

private:
    using First = std::tuple_element_t<0, std::tuple<Ts...>>;

    bool hasAll(Entity e) const {
        return std::apply([&](const auto*... pool) { return (pool->contains(e) && ...); }, pools_);
    }
    // Moves an entity that has all of Ts (and is past the prefix) to the end of the prefix.
    void pushBack(Entity e) {
        std::apply([&](auto*... pool) { (pool->swapSlots(pool->slotOf(e), uint32_t(size_)), ...); },
                   pools_);
        ++size_;
    }

    std::tuple<ComponentPool<Ts>*...> pools_;
    size_t size_ = 0;
};

// A handle on an owning group (cheap to copy, valid as long as its registry).
template <class... Ts>
class Group {
    using Data = std::tuple<Ts*...>;

public:
    // The handle of the registry's group state.
    explicit Group(GroupData<Ts...>& data) : data_(&data) {}

    // Number of entities that have all of Ts.
    size_t size() const { return data_->size(); }
    // Whether the entity has all of Ts.
    bool contains(Entity e) const { return std::get<0>(data_->pools())->slotOf(e) < size(); }
    // The grouped entities, in iteration order.
    std::span<const Entity> entities() const {
        return {std::get<0>(data_->pools())->entities().data(), size()};
    }

    // Calls f(entity, components&...) for every entity in the group: a loop over dense arrays.
    template <class F>
    void forEach(F&& f) const {
        const Entity* entities = std::get<0>(data_->pools())->entities().data();
        Data data = componentData();
        size_t count = size();
        for (size_t i = 0; i < count; ++i) {
            [&]<size_t... I>(std::index_sequence<I...>) {
                f(entities[i], std::get<I>(data)[i]...);
            }
            (std::index_sequence_for<Ts...>{});
        }
    }

    class Iterator {
    public:
        // Position i of the group's prefix.
        Iterator(const Entity* entities, const Data& data, size_t i)
            : entities_(entities), data_(data), i_(i) {}
        // (entity, components&...) of the current entity.
        std::tuple<Entity, Ts&...> operator*() const {
            return [&]<size_t... I>(std::index_sequence<I...>) {
                return std::tuple<Entity, Ts&...>{entities_[i_], std::get<I>(data_)[i_]...};
            }
            (std::index_sequence_for<Ts...>{});
        }
        // Advances to the next entity.
        Iterator& operator++() {
            ++i_;
            return *this;
        }
        // Whether the two iterators are at different positions.
        bool operator!=(const Iterator& o) const { return i_ != o.i_; }

    private:
        const Entity* entities_;
        Data data_;
        size_t i_;
    };

    // The group's entities and components as read when each() was called.
    struct Range {
        const Entity* entities;  // the first owned pool's dense entities
        Data data;               // every owned pool's dense components
        size_t count;            // the group's size
        // The first entity of the group.
        Iterator begin() const { return Iterator(entities, data, 0); }
        // Past the last entity of the group.
        Iterator end() const { return Iterator(entities, data, count); }
    };

    // for (auto [e, a, b] : group.each()) ...: lazy, no allocation.
    Range each() const {
        return Range{std::get<0>(data_->pools())->entities().data(), componentData(), size()};
    }

private:
    Data componentData() const {
        return std::apply([](auto*... pool) { return Data{pool->components().data()...}; },
                          data_->pools());
    }

    GroupData<Ts...>* data_;
};

}  // namespace onelight::ecs
