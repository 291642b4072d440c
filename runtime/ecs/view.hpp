// Views: the entities present in every one of a few pools, found by walking the dense entities
// of the smallest pool and looking each one up in the sparse arrays of the others. A view never
// creates a pool; a component type without a pool makes the view empty. `View<const T>` yields
// `const T&` (Registry::view() const gives only such views).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "sparse_set.hpp"

namespace onelight::ecs {

// The pool type behind a view over T: read-only when T is const.
template <class T>
using PoolFor = std::conditional_t<std::is_const_v<T>, const ComponentPool<std::remove_const_t<T>>,
                                   ComponentPool<T>>;

// Iterates the entities present in every pool, in the dense order of the pool that was smallest
// when the view was made; each() yields (entity, components&...).
template <class... Ts>
class View {
    static constexpr size_t kCount = sizeof...(Ts);
    using Slots = std::array<uint32_t, kCount>;
    using Finders = std::array<SlotFinder, kCount>;
    using Data = std::tuple<Ts*...>;

public:
    // Any null pool (a component type nobody has) makes the view empty.
    explicit View(PoolFor<Ts>*... pools) : pools_(pools...) {
        if (!(pools && ...)) return;
        size_t smallest = SIZE_MAX;
        size_t k = 0;
        auto consider = [&](const auto* pool) {
            if (pool->size() < smallest)
                smallest = pool->size(), lead_ = &pool->entities(), leadIndex_ = k;
            ++k;
        };
        (consider(pools), ...);
    }

    // Calls f(entity, components&...) for every entity in the view: one sparse lookup per
    // entity and non-leading pool, none for the leading one.
    template <class F>
    void forEach(F&& f) const {
        if (!lead_) return;
        [&]<size_t... L>(std::index_sequence<L...>) {
            ((leadIndex_ == L ? forEachLedBy<L>(f) : void()), ...);
        }
        (std::index_sequence_for<Ts...>{});
    }

    class Iterator {
    public:
        // The first entity at or after position i of the leading pool that is in the view.
        Iterator(const View& view, size_t i) : i_(i), leadIndex_(view.leadIndex_) {
            if (view.lead_) {
                entities_ = view.lead_->data();
                count_ = view.lead_->size();
                data_ = view.componentData();
                finders_ = view.slotFinders();
            }
            skip();
        }
        // (entity, components&...) of the current entity.
        std::tuple<Entity, Ts&...> operator*() const {
            return [&]<size_t... I>(std::index_sequence<I...>) {
                return std::tuple<Entity, Ts&...>{entities_[i_], std::get<I>(data_)[slots_[I]]...};
            }
            (std::index_sequence_for<Ts...>{});
        }
        // Advances to the next entity in the view.
        Iterator& operator++() {
            ++i_;
            skip();
            return *this;
        }
        // Whether the two iterators are at different positions.
        bool operator!=(const Iterator& o) const { return i_ != o.i_; }

    private:
        void skip() {
            for (; i_ < count_; ++i_) {
                Entity e = entities_[i_];
                bool found = [&]<size_t... I>(std::index_sequence<I...>) {
                    return ((slots_[I] = I == leadIndex_ ? uint32_t(i_) : finders_[I](e),
                             slots_[I] != kNoSlot) &&
                            ...);
                }
                (std::index_sequence_for<Ts...>{});
                if (found) return;
            }
        }
        size_t i_;
        size_t leadIndex_;
        const Entity* entities_ = nullptr;
        size_t count_ = 0;
        Data data_{};
        Finders finders_{};
        Slots slots_{};
    };

    // Holds the view by value: `for (... : registry.view<A, B>().each())` outlives the
    // temporary view (a View is a few pointers, cheap to copy).
    struct Range {
        View view;  // the view iterated
        // The first entity in the view.
        Iterator begin() const { return Iterator(view, 0); }
        // Past the last entity in the view.
        Iterator end() const { return Iterator(view, view.lead_ ? view.lead_->size() : 0); }
    };

    // for (auto [e, a, b] : view.each()) ...: lazy, no allocation.
    Range each() const { return Range{*this}; }

private:
    // forEach with the leading pool known at compile time (L), so that it is never looked up.
    template <size_t L, class F>
    void forEachLedBy(F& f) const {
        const Entity* entities = lead_->data();
        size_t count = lead_->size();
        Data data = componentData();
        Finders finders = slotFinders();
        for (size_t i = 0; i < count; ++i) {
            Entity e = entities[i];
            [&]<size_t... I>(std::index_sequence<I...>) {
                Slots slots;
                if (((slots[I] = I == L ? uint32_t(i) : finders[I](e), slots[I] != kNoSlot) && ...))
                    f(e, std::get<I>(data)[slots[I]]...);
            }
            (std::index_sequence_for<Ts...>{});
        }
    }
    // The start of every pool's dense components, read when iteration starts.
    Data componentData() const {
        return [&]<size_t... I>(std::index_sequence<I...>) {
            return Data{std::get<I>(pools_)->components().data()...};
        }
        (std::index_sequence_for<Ts...>{});
    }
    // Every pool's lookup arrays, read when iteration starts.
    Finders slotFinders() const {
        return [&]<size_t... I>(std::index_sequence<I...>) {
            return Finders{std::get<I>(pools_)->finder()...};
        }
        (std::index_sequence_for<Ts...>{});
    }

    std::tuple<PoolFor<Ts>*...> pools_;
    const std::vector<Entity>* lead_ = nullptr;  // dense entities of the smallest pool
    size_t leadIndex_ = 0;                       // which of pools_ leads
};

}  // namespace onelight::ecs
