#include "io/rawlog/AllocationBudget.h"

#include <dlfcn.h>
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
// Each one charges the active budget, then forwards to the next definition in the process
// (libstdc++, or AddressSanitizer's when it is loaded, which keeps its checks intact).
namespace {

template <typename Fn>
Fn nextDefinition(const char* mangled_name) {
    void* fn = dlsym(RTLD_NEXT, mangled_name);
    if (fn == nullptr) std::abort();  // cannot happen with a C++ runtime loaded
    return reinterpret_cast<Fn>(fn);
}

using NewFn = void* (*)(std::size_t);
using AlignedNewFn = void* (*)(std::size_t, std::align_val_t);

}  // namespace

void* operator new(std::size_t size) {
    static const NewFn next = nextDefinition<NewFn>("_Znwm");
    stairmap::io::AllocationBudget::charge(size);
    return next(size);
}

void* operator new[](std::size_t size) {
    static const NewFn next = nextDefinition<NewFn>("_Znam");
    stairmap::io::AllocationBudget::charge(size);
    return next(size);
}

void* operator new(std::size_t size, std::align_val_t alignment) {
    static const AlignedNewFn next = nextDefinition<AlignedNewFn>("_ZnwmSt11align_val_t");
    stairmap::io::AllocationBudget::charge(size);
    return next(size, alignment);
}

void* operator new[](std::size_t size, std::align_val_t alignment) {
    static const AlignedNewFn next = nextDefinition<AlignedNewFn>("_ZnamSt11align_val_t");
    stairmap::io::AllocationBudget::charge(size);
    return next(size, alignment);
}

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
