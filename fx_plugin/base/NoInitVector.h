#pragma once
// A std::vector whose resize() leaves new elements unwritten: for arrays of plain floats that a
// loop fills right after (DrawList's instances, the builder's scratch), where value-initialising
// them first would write every byte twice. Only for aggregates of arithmetic members.
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace fx {

template <class T>
struct NoInitAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = NoInitAllocator<U>;
    };
    NoInitAllocator() = default;
    template <class U>
    NoInitAllocator(const NoInitAllocator<U>&) noexcept {}
    template <class U>
    void construct(U*) noexcept {
        static_assert(std::is_trivially_copyable<U>::value && std::is_trivially_destructible<U>::value,
                      "only for plain data");
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

template <class T>
using NoInitVector = std::vector<T, NoInitAllocator<T>>;

}  // namespace fx
