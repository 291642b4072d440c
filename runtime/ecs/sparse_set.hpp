// A component pool: a sparse array from entity index to a dense slot, and dense arrays of
// entities and components (EnTT's sparse set). Iteration is over the dense arrays, in an order
// fixed by the sequence of insertions and removals, so equal histories iterate equally.
// A pool may be owned by one group (group.hpp), which it tells of every insertion and removal
// so that the group keeps the entities it matches packed at the front of the dense arrays.
#pragma once

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "entity.hpp"

namespace onelight::ecs {

// The dense slot of an entity that a pool does not hold.
inline constexpr uint32_t kNoSlot = 0xFFFFFFFFu;

// The type-erased face of a pool, so that the registry can drop an entity from every pool.
struct PoolBase {
    virtual ~PoolBase() = default;
    // Removes the entity's component if it has one.
    virtual void removeIfPresent(Entity e) = 0;
    // Whether the entity has a component in this pool.
    virtual bool contains(Entity e) const = 0;
    // Number of components (entities) in the pool.
    virtual size_t size() const = 0;
};

// What a pool tells the group that owns it (group.hpp), so that the group keeps its prefix.
struct PoolOwner {
    virtual ~PoolOwner() = default;
    // Called once the entity has been added to one of the owned pools.
    virtual void afterEmplace(Entity e) = 0;
    // Called just before the entity leaves one of the owned pools.
    virtual void beforeRemove(Entity e) = 0;
};

template <class... Ts>
class GroupData;

// The arrays ComponentPool::slotOf reads, copied out for a loop (stale after any structural
// change to the pool).
struct SlotFinder {
    const uint32_t* sparse = nullptr;  // entity index -> dense slot
    uint32_t sparseSize = 0;           // entries in sparse
    const Entity* entities = nullptr;  // dense entities
    // The dense slot of the entity, or kNoSlot when the pool lacks it.
    uint32_t operator()(Entity e) const {
        uint32_t i = indexOf(e);
        if (i >= sparseSize) return kNoSlot;
        uint32_t slot = sparse[i];
        return slot != kNoSlot && entities[slot] == e ? slot : kNoSlot;
    }
};

template <class T>
class ComponentPool final : public PoolBase {
public:
    // The dense slot of the entity's component, or kNoSlot when it has none (stale handles too).
    uint32_t slotOf(Entity e) const { return finder()(e); }
    // Whether the entity has a component here.
    bool contains(Entity e) const override { return slotOf(e) != kNoSlot; }
    // Number of components.
    size_t size() const override { return entities_.size(); }

    // Adds the component; the entity must not have one yet. The reference is to the stored
    // component (an owning group may have moved it to another slot).
    template <class... Args>
    T& emplace(Entity e, Args&&... args) {
        assert(!contains(e) && "ComponentPool::emplace: the entity already has this component");
        uint32_t i = indexOf(e);
        if (i >= sparse_.size()) sparse_.resize(i + 1, kNoSlot);
        sparse_[i] = uint32_t(entities_.size());
        entities_.push_back(e);
        components_.push_back(T{std::forward<Args>(args)...});
        if (owner_) owner_->afterEmplace(e);
        return components_[sparse_[i]];
    }

    // Removes by moving the last element into the hole (O(1)).
    void remove(Entity e) {
        assert(contains(e) && "ComponentPool::remove: the entity has no such component");
        if (owner_) owner_->beforeRemove(e);
        uint32_t slot = sparse_[indexOf(e)];
        uint32_t last = uint32_t(entities_.size()) - 1;
        if (slot != last) {
            entities_[slot] = entities_[last];
            components_[slot] = std::move(components_[last]);
            sparse_[indexOf(entities_[slot])] = slot;
        }
        entities_.pop_back();
        components_.pop_back();
        sparse_[indexOf(e)] = kNoSlot;
    }
    // Removes the entity's component if it has one.
    void removeIfPresent(Entity e) override {
        if (contains(e)) remove(e);
    }

    // The entity's component; it must have one.
    T& get(Entity e) {
        assert(contains(e) && "ComponentPool::get: the entity has no such component");
        return components_[sparse_[indexOf(e)]];
    }
    // The entity's component, read-only; it must have one.
    const T& get(Entity e) const {
        assert(contains(e) && "ComponentPool::get: the entity has no such component");
        return components_[sparse_[indexOf(e)]];
    }
    // The entity's component, or null when it has none.
    T* tryGet(Entity e) {
        uint32_t slot = slotOf(e);
        return slot != kNoSlot ? &components_[slot] : nullptr;
    }
    // The entity's component, read-only, or null when it has none.
    const T* tryGet(Entity e) const {
        uint32_t slot = slotOf(e);
        return slot != kNoSlot ? &components_[slot] : nullptr;
    }

    // The dense entities, in iteration order.
    const std::vector<Entity>& entities() const { return entities_; }
    // The dense components, parallel to entities().
    std::vector<T>& components() { return components_; }
    // The dense components, read-only, parallel to entities().
    const std::vector<T>& components() const { return components_; }
    // slotOf's arrays, for a loop that makes no structural change.
    SlotFinder finder() const {
        return {sparse_.data(), uint32_t(sparse_.size()), entities_.data()};
    }
    // The group that owns this pool, or null.
    const PoolOwner* owner() const { return owner_; }

private:
    template <class... Ts>
    friend class GroupData;

    // Exchanges two dense slots (entities, components and their sparse entries).
    void swapSlots(uint32_t a, uint32_t b) {
        if (a == b) return;
        using std::swap;
        swap(entities_[a], entities_[b]);
        swap(components_[a], components_[b]);
        sparse_[indexOf(entities_[a])] = a;
        sparse_[indexOf(entities_[b])] = b;
    }

    std::vector<uint32_t> sparse_;  // entity index -> dense slot, kNoSlot when none
    std::vector<Entity> entities_;  // dense
    std::vector<T> components_;     // dense, parallel to entities_
    PoolOwner* owner_ = nullptr;    // the owning group, if any
};

}  // namespace onelight::ecs
