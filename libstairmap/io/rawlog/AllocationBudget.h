#pragma once
// A cap on what one block of code may allocate, checked *before* each allocation.
//
// Why: MRPT's deserializers resize containers to sizes read from the file before reading the
// data, so one damaged byte in a rawlog asks for gigabytes (a string length of 4 GB, a point
// count of 2^32), which Linux grants and then fills with zeros. While an AllocationBudget is
// alive on a thread, every request that thread makes through `operator new` (all C++ containers
// and strings) or `mrpt::aligned_malloc` (MRPT's aligned vectors, point maps, matrices) is
// added up; a request that would exceed the budget throws AllocationBudgetExceeded (a
// std::bad_alloc) instead, so the deserializer unwinds normally and frees what it built.
//
// The check lives in replacement allocation functions (operator new/delete, all forms, on
// malloc/free; and mrpt::aligned_malloc) defined in AllocationBudget.cpp; they cost one
// thread-local read per allocation when no budget is active. Frees are not credited back: the budget bounds
// the total requested inside the block, which is what matters for one deserialized object.

#include <cstdint>
#include <new>

namespace stairmap::io {

/// Thrown when an allocation inside an AllocationBudget would exceed it.
class AllocationBudgetExceeded : public std::bad_alloc {
public:
    AllocationBudgetExceeded(std::uint64_t request, std::uint64_t used, std::uint64_t limit);
    const char* what() const noexcept override { return message_; }

private:
    char message_[192];  // no heap: it is built where the heap is being refused
};

/// RAII: caps allocations on the calling thread while alive. Budgets nest: a request must fit
/// in every enclosing budget and counts against all of them. limit_bytes == 0: no cap.
class AllocationBudget {
public:
    explicit AllocationBudget(std::uint64_t limit_bytes);
    ~AllocationBudget();
    AllocationBudget(const AllocationBudget&) = delete;
    AllocationBudget& operator=(const AllocationBudget&) = delete;

    /// [bytes] granted so far inside this budget (refused requests are not counted).
    std::uint64_t used() const { return used_; }

    /// Called by the replacement allocators: counts `bytes` against the active budget of this
    /// thread, or throws AllocationBudgetExceeded. No-op when no budget is active.
    static void charge(std::size_t bytes);

private:
    AllocationBudget* outer_;
    std::uint64_t limit_;
    std::uint64_t used_ = 0;
};

}  // namespace stairmap::io
