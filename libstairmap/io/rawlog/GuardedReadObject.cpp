#include "io/rawlog/GuardedReadObject.h"

#include <stdexcept>
#include <string>

#include "io/rawlog/AllocationBudget.h"

namespace stairmap::io {

mrpt::serialization::CSerializable::Ptr guardedReadObject(mrpt::serialization::CArchive& archive,
                                                          std::uint64_t max_object_bytes) {
    try {
        const AllocationBudget budget(max_object_bytes);  // gone before the handler runs
        return archive.ReadObject();
    } catch (const AllocationBudgetExceeded& e) {
        throw std::runtime_error("object needs more memory than the " +
                                 std::to_string(max_object_bytes >> 20) + " MiB allowed: " + e.what());
    }
}

}  // namespace stairmap::io
