// The registry: creates and destroys entities and owns one pool per component type.
//   Registry r;
//   Entity e = r.create();
//   r.emplace<Position>(e, 0.f, 1.f, 0.f);
//   for (auto [e, p, v] : r.view<Position, Velocity>().each()) p.x += v.x;
// Structural changes (create, destroy, emplace, remove) must not happen while iterating a view
// of the pools they touch; collect the entities first.
#pragma once

#include <cassert>
#include <cstdint>
#include <deque>
#include <memory>
#include <tuple>
#include <typeindex>
#include <unordered_map>
#include <vector>

#include "sparse_set.hpp"

namespace onelight::ecs {

template <class... Ts>
class View;

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

    // Drops the entity and all its components; its handle becomes invalid.
    void destroy(Entity e) {
        assert(valid(e) && "Registry::destroy: invalid entity");
        for (auto& [type, pool] : pools_) pool->removeIfPresent(e);
        freeSlots_.push_back(indexOf(e));
        slots_[indexOf(e)] = makeEntity(kIndexMask, generationOf(e));  // marks the slot free
    }

    // Whether the handle names a live entity (not destroyed, not a stale generation).
    bool valid(Entity e) const { return indexOf(e) < slots_.size() && slots_[indexOf(e)] == e; }

    // Live entities.
    size_t alive() const { return slots_.size() - freeSlots_.size(); }

    template <class T, class... Args>
    T& emplace(Entity e, Args&&... args) {
        assert(valid(e) && "Registry::emplace: invalid entity");
        return pool<T>().emplace(e, std::forward<Args>(args)...);
    }
    template <class T>
    void remove(Entity e) {
        assert(valid(e) && "Registry::remove: invalid entity");
        pool<T>().remove(e);
    }
    template <class T>
    T& get(Entity e) {
        assert(valid(e) && "Registry::get: invalid entity");
        return pool<T>().get(e);
    }
    // Read-only access; the entity must have the component.
    template <class T>
    const T& get(Entity e) const {
        assert(valid(e) && "Registry::get: invalid entity");
        auto it = pools_.find(std::type_index(typeid(T)));
        assert(it != pools_.end() && "Registry::get: no entity has this component");
        return static_cast<const ComponentPool<T>&>(*it->second).get(e);
    }
    template <class T>
    T* tryGet(Entity e) {
        return valid(e) ? pool<T>().tryGet(e) : nullptr;
    }
    template <class... Ts>
    bool allOf(Entity e) {
        return valid(e) && (pool<Ts>().contains(e) && ...);
    }

    // Entities that have every component Ts, iterated in the dense order of the smallest pool.
    template <class... Ts>
    View<Ts...> view() {
        return View<Ts...>(pool<Ts>()...);
    }

    // The pool of component type T (created on first use).
    template <class T>
    ComponentPool<T>& pool() {
        std::unique_ptr<PoolBase>& p = pools_[std::type_index(typeid(T))];
        if (!p) p = std::make_unique<ComponentPool<T>>();
        return static_cast<ComponentPool<T>&>(*p);
    }

private:
    std::vector<Entity> slots_;       // per index: the live handle, or a free marker
    std::deque<uint32_t> freeSlots_;  // indices to reuse, oldest first
    std::unordered_map<std::type_index, std::unique_ptr<PoolBase>> pools_;
};

// Iterates the entities present in every pool; each() yields (entity, components&...).
template <class... Ts>
class View {
public:
    explicit View(ComponentPool<Ts>&... pools) : pools_(pools...) {
        size_t smallest = SIZE_MAX;
        ((pools.size() < smallest ? (smallest = pools.size(), lead_ = &pools.entities()) : lead_),
         ...);
    }

    // Calls f(entity, components&...) for every entity in the view: one sparse lookup per
    // pool and entity (tryGet), none twice.
    template <class F>
    void forEach(F&& f) {
        for (Entity e : *lead_) {
            std::tuple<Ts*...> found{std::get<ComponentPool<Ts>&>(pools_).tryGet(e)...};
            if ((std::get<Ts*>(found) && ...)) f(e, *std::get<Ts*>(found)...);
        }
    }

    class Iterator {
    public:
        Iterator(View* view, size_t i) : view_(view), i_(i) { skip(); }
        std::tuple<Entity, Ts&...> operator*() const {
            Entity e = (*view_->lead_)[i_];
            return {e, std::get<ComponentPool<Ts>&>(view_->pools_).get(e)...};
        }
        Iterator& operator++() {
            ++i_;
            skip();
            return *this;
        }
        bool operator!=(const Iterator& o) const { return i_ != o.i_; }

    private:
        void skip() {
            while (i_ < view_->lead_->size() && !view_->hasAll((*view_->lead_)[i_])) ++i_;
        }
        View* view_;
        size_t i_;
    };

    // Holds the view by value: `for (... : registry.view<A, B>().each())` outlives the
    // temporary view (a View is a few references, cheap to copy).
    struct Range {
        View view;
        Iterator begin() { return Iterator(&view, 0); }
        Iterator end() { return Iterator(&view, view.lead_->size()); }
    };

    // for (auto [e, a, b] : view.each()) ...: lazy, no allocation.
    Range each() const { return Range{*this}; }

private:
    bool hasAll(Entity e) const {
        return (std::get<ComponentPool<Ts>&>(pools_).contains(e) && ...);
    }
    std::tuple<ComponentPool<Ts>&...> pools_;
    const std::vector<Entity>* lead_ = nullptr;
};

}  // namespace onelight::ecs
