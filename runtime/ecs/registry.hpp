// The registry: creates and destroys entities and owns one pool per component type.
//   Registry r;
//   Entity e = r.create();
//   r.emplace<Position>(e, 0.f, 1.f, 0.f);
//   for (auto [e, p, v] : r.view<Position, Velocity>().each()) p.x += v.x;
//   auto moving = r.group<Position, Velocity>();  // owns both pools: dense, lookup-free loops
//   moving.forEach([](Entity, Position& p, Velocity& v) { p.x += v.x; });
// Only emplace, pool() and group() create pools; reads (views, get, tryGet, allOf) never do,
// and a const Registry& gives views of const components.
// Structural changes (create, destroy, emplace, remove) must not happen while iterating a view
// or group of the pools they touch; collect the entities first.
#pragma once

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <deque>
#include <memory>
#include <type_traits>
#include <typeindex>
#include <unordered_map>
#include <vector>

#include "group.hpp"
#include "sparse_set.hpp"
#include "view.hpp"

namespace onelight::ecs {

class Registry {
public:
    // A new entity, reusing a destroyed slot (oldest first) with the next generation.
    Entity create() {
        if (!freeSlots_.empty()) {
            uint32_t index = freeSlots_.front();
            freeSlots_.pop_front();
            return slots_[index] = makeEntity(index, generationOf(slots_[index]) + 1);
        }
        assert(slots_.size() <= kIndexMask && "Registry::create: out of entity indices");
        slots_.push_back(makeEntity(uint32_t(slots_.size()), 0));
        return slots_.back();
    }

    // Drops the entity and all its components (pools in creation order); its handle becomes
    // invalid.
    void destroy(Entity e) {
        assert(valid(e) && "Registry::destroy: invalid entity");
        for (const std::unique_ptr<PoolBase>& pool : pools_) pool->removeIfPresent(e);
        freeSlots_.push_back(indexOf(e));
        slots_[indexOf(e)] = makeEntity(kIndexMask, generationOf(e));  // marks the slot free
    }

    // Whether the handle names a live entity (not destroyed, not a stale generation).
    bool valid(Entity e) const { return indexOf(e) < slots_.size() && slots_[indexOf(e)] == e; }

    // Live entities.
    size_t alive() const { return slots_.size() - freeSlots_.size(); }

    // Adds a component T (creating its pool on first use); the entity must not have one.
    template <class T, class... Args>
    T& emplace(Entity e, Args&&... args) {
        assert(valid(e) && "Registry::emplace: invalid entity");
        return pool<T>().emplace(e, std::forward<Args>(args)...);
    }
    // Removes the entity's component T; it must have one.
    template <class T>
    void remove(Entity e) {
        assert(valid(e) && "Registry::remove: invalid entity");
        ComponentPool<T>* p = find<T>();
        assert(p && "Registry::remove: no entity has this component");
        p->remove(e);
    }
    // The entity's component T; it must have one.
    template <class T>
    T& get(Entity e) {
        assert(valid(e) && "Registry::get: invalid entity");
        ComponentPool<T>* p = find<T>();
        assert(p && "Registry::get: no entity has this component");
        return p->get(e);
    }
    // Read-only access; the entity must have the component.
    template <class T>
    const T& get(Entity e) const {
        assert(valid(e) && "Registry::get: invalid entity");
        const ComponentPool<T>* p = find<T>();
        assert(p && "Registry::get: no entity has this component");
        return p->get(e);
    }
    // The entity's component T, or null (also for an invalid handle).
    template <class T>
    T* tryGet(Entity e) {
        ComponentPool<T>* p = find<T>();
        return p && valid(e) ? p->tryGet(e) : nullptr;
    }
    // The entity's component T, read-only, or null (also for an invalid handle).
    template <class T>
    const T* tryGet(Entity e) const {
        const ComponentPool<T>* p = find<T>();
        return p && valid(e) ? p->tryGet(e) : nullptr;
    }
    // Whether the handle is valid and the entity has every component Ts.
    template <class... Ts>
    bool allOf(Entity e) const {
        return valid(e) && (hasComponent<Ts>(e) && ...);
    }

    // Entities that have every component Ts, iterated in the dense order of the pool that is
    // smallest now; Ts may be const (`view<const A, B>()`). Empty if some Ts has no pool (a pool
    // created later does not join this view: make views just before iterating).
    template <class... Ts>
    View<Ts...> view() {
        return View<Ts...>(find<std::remove_const_t<Ts>>()...);
    }
    // The same over const components, from a const registry.
    template <class... Ts>
    View<std::add_const_t<Ts>...> view() const {
        return View<std::add_const_t<Ts>...>(find<std::remove_const_t<Ts>>()...);
    }

    // The owning group of Ts (made on first use, creating the pools; see group.hpp). A pool is
    // owned by one group at most: asking for a group that shares a pool with another aborts.
    template <class... Ts>
    Group<Ts...> group() {
        for (const std::unique_ptr<PoolOwner>& g : groups_)
            if (auto* data = dynamic_cast<GroupData<Ts...>*>(g.get())) return Group<Ts...>(*data);
        if (!((pool<Ts>().owner() == nullptr) && ...)) {
            assert(false && "Registry::group: a pool is already owned by another group");
            std::abort();
        }
        auto data = std::make_unique<GroupData<Ts...>>(pool<Ts>()...);
        Group<Ts...> handle(*data);
        groups_.push_back(std::move(data));
        return handle;
    }

    // The pool of component type T (created on first use).
    template <class T>
    ComponentPool<T>& pool() {
        if (ComponentPool<T>* p = find<T>()) return *p;
        auto p = std::make_unique<ComponentPool<T>>();
        ComponentPool<T>& created = *p;
        byType_.emplace(std::type_index(typeid(T)), p.get());
        pools_.push_back(std::move(p));
        return created;
    }
    // The pool of component type T, or null if nothing created it yet (never creates one).
    template <class T>
    const ComponentPool<T>* findPool() const {
        return find<T>();
    }
    // Whether component type T has a pool.
    template <class T>
    bool hasPool() const {
        return find<T>() != nullptr;
    }
    // Number of pools (component types ever emplaced or asked for with pool() or group()).
    size_t poolCount() const { return pools_.size(); }

private:
    template <class T>
    ComponentPool<T>* find() const {
        static_assert(!std::is_const_v<T>, "Registry::find: the component type, not const");
        auto it = byType_.find(std::type_index(typeid(T)));
        return it != byType_.end() ? static_cast<ComponentPool<T>*>(it->second) : nullptr;
    }
    template <class T>
    bool hasComponent(Entity e) const {
        const ComponentPool<T>* p = find<T>();
        return p && p->contains(e);
    }

    std::vector<Entity> slots_;                     // per index: the live handle, or a free marker
    std::deque<uint32_t> freeSlots_;                // indices to reuse, oldest first
    std::vector<std::unique_ptr<PoolBase>> pools_;  // in creation order
    std::unordered_map<std::type_index, PoolBase*> byType_;  // component type -> its pool
    std::vector<std::unique_ptr<PoolOwner>> groups_;         // owning groups, in creation order
};

}  // namespace onelight::ecs
