// A component pool: a sparse array from entity index to a dense slot, and dense arrays of
// entities and components (EnTT's sparse set). Iteration is over the dense arrays, in an order
// fixed by the sequence of insertions and removals, so equal histories iterate equally.
#pragma once

#include <cassert>
#include <cstdint>
#include <utility>
#include <vector>

#include "entity.hpp"

namespace onelight::ecs {

// The type-erased face of a pool, so that the registry can drop an entity from every pool.
struct PoolBase {
    virtual ~PoolBase() = default;
    virtual void removeIfPresent(Entity e) = 0;
    virtual bool contains(Entity e) const = 0;
    virtual size_t size() const = 0;
};

template <class T>
class ComponentPool final : public PoolBase {
public:
    bool contains(Entity e) const override {
        uint32_t i = indexOf(e);
        return i < sparse_.size() && sparse_[i] != kAbsent && entities_[sparse_[i]] == e;
    }
    size_t size() const override { return entities_.size(); }

    // Adds the component; the entity must not have one yet.
    template <class... Args>
    T& emplace(Entity e, Args&&... args) {
        assert(!contains(e) && "ComponentPool::emplace: the entity already has this component");
        uint32_t i = indexOf(e);
        if (i >= sparse_.size()) sparse_.resize(i + 1, kAbsent);
        sparse_[i] = uint32_t(entities_.size());
        entities_.push_back(e);
        components_.push_back(T{std::forward<Args>(args)...});
        return components_.back();
    }

    // Removes by moving the last element into the hole (O(1)).
    void remove(Entity e) {
        assert(contains(e) && "ComponentPool::remove: the entity has no such component");
        uint32_t slot = sparse_[indexOf(e)];
        uint32_t last = uint32_t(entities_.size()) - 1;
        if (slot != last) {
            entities_[slot] = entities_[last];
            components_[slot] = std::move(components_[last]);
            sparse_[indexOf(entities_[slot])] = slot;
        }
        entities_.pop_back();
        components_.pop_back();
        sparse_[indexOf(e)] = kAbsent;
    }
    void removeIfPresent(Entity e) override {
        if (contains(e)) remove(e);
    }

    T& get(Entity e) {
        assert(contains(e) && "ComponentPool::get: the entity has no such component");
        return components_[sparse_[indexOf(e)]];
    }
    const T& get(Entity e) const {
        assert(contains(e) && "ComponentPool::get: the entity has no such component");
        return components_[sparse_[indexOf(e)]];
    }
    T* tryGet(Entity e) { return contains(e) ? &components_[sparse_[indexOf(e)]] : nullptr; }

    const std::vector<Entity>& entities() const { return entities_; }
    std::vector<T>& components() { return components_; }

private:
    static constexpr uint32_t kAbsent = 0xFFFFFFFFu;
    std::vector<uint32_t> sparse_;  // entity index -> dense slot, kAbsent when none
    std::vector<Entity> entities_;  // dense
    std::vector<T> components_;     // dense, parallel to entities_
};

}  // namespace onelight::ecs
