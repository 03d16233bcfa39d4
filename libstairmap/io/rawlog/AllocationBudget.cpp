#include "io/rawlog/AllocationBudget.h"

#include <mrpt/core/aligned_allocator.h>

#include <cinttypes>
#include <cstdio>
#include <cstdlib>

namespace stairmap::io {
namespace {

thread_local AllocationBudget* t_active = nullptr;

}  // namespace

AllocationBudgetExceeded::AllocationBudgetExceeded(std::uint64_t request, std::uint64_t used,
                                                   std::uint64_t limit) {
    std::snprintf(message_, sizeof message_,
                  "allocation of %" PRIu64 " bytes refused, %" PRIu64 " of the %" PRIu64
                  " bytes allowed for one object already taken (corrupt size field?)",
                  request, used, limit);
}

AllocationBudget::AllocationBudget(std::uint64_t limit_bytes)
    : outer_(t_active), limit_(limit_bytes > 0 ? limit_bytes : UINT64_MAX) {
    t_active = this;
}

AllocationBudget::~AllocationBudget() { t_active = outer_; }

void AllocationBudget::charge(std::size_t bytes) {
    // Every enclosing budget must have room: an inner budget cannot lend what an outer lacks.
    for (AllocationBudget* b = t_active; b != nullptr; b = b->outer_) {
        if (bytes > b->limit_ - b->used_) throw AllocationBudgetExceeded(bytes, b->used_, b->limit_);
    }
    for (AllocationBudget* b = t_active; b != nullptr; b = b->outer_) b->used_ += bytes;
}

}  // namespace stairmap::io

// ---- replacement allocation functions ------------------------------------------------------
// The standard allows a program to replace operator new/delete. Every form is replaced, on
// malloc / aligned_alloc / free, so that each pair stays consistent whatever else defines them
// (libstdc++, or a sanitizer runtime linked into the executable: forwarding to "the next"
// operator new instead mixed allocators under clang's static ASan runtime).
namespace {

void* allocateOrThrow(std::size_t size) {
    stairmap::io::AllocationBudget::charge(size);
    for (;;) {
        if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
        std::new_handler handler = std::get_new_handler();
        if (handler == nullptr) throw std::bad_alloc();
        handler();
    }
}

void* allocateAlignedOrThrow(std::size_t size, std::align_val_t alignment) {
    stairmap::io::AllocationBudget::charge(size);
    const auto align = static_cast<std::size_t>(alignment);
    const std::size_t rounded = (size + align - 1) / align * align;  // aligned_alloc's rule
    for (;;) {
        if (void* p = std::aligned_alloc(align, rounded == 0 ? align : rounded)) return p;
        std::new_handler handler = std::get_new_handler();
        if (handler == nullptr) throw std::bad_alloc();
        handler();
    }
}

template <typename Fn>
void* noThrow(Fn&& allocate) noexcept {
    try {
        return allocate();
    } catch (...) {
        return nullptr;
    }
}

}  // namespace

void* operator new(std::size_t n) { return allocateOrThrow(n); }
void* operator new[](std::size_t n) { return allocateOrThrow(n); }
void* operator new(std::size_t n, std::align_val_t a) { return allocateAlignedOrThrow(n, a); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocateAlignedOrThrow(n, a); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    return noThrow([&] { return allocateOrThrow(n); });
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    return noThrow([&] { return allocateOrThrow(n); });
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return noThrow([&] { return allocateAlignedOrThrow(n, a); });
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return noThrow([&] { return allocateAlignedOrThrow(n, a); });
}

void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }

// MRPT's own aligned allocator (libmrpt-core) is called through the PLT by every MRPT library,
// so this definition replaces it process-wide. Same contract as MRPT 2.5's (size rounded up to
// a multiple of the alignment, memory from aligned_alloc, freed by mrpt::aligned_free = free),
// plus the budget check, and std::bad_alloc instead of a null pointer that MRPT's callers would
// write through.
void* mrpt::aligned_malloc(std::size_t size, std::size_t alignment) {
    stairmap::io::AllocationBudget::charge(size);
    if (alignment != 0 && size % alignment != 0) size = (size / alignment + 1) * alignment;
    void* p = std::aligned_alloc(alignment, size);
    if (p == nullptr && size != 0) throw std::bad_alloc();
    return p;
}
