#pragma once
// Reading one object from an MRPT archive so that corrupt data cannot exhaust memory.
//
// MRPT's deserializers resize containers to sizes read from the file before reading the data,
// so a corrupt size asks for gigabytes before anything can tell the data is short. The object
// is therefore read under an AllocationBudget: an allocation that would take the object past
// `max_object_bytes` throws before it happens, the deserializer unwinds (freeing what it built)
// and the damage is reported like a truncation. Single-threaded per archive; other threads are
// not affected.

#include <mrpt/serialization/CArchive.h>

#include <cstdint>

namespace stairmap::io {

/// archive.ReadObject() with its allocations capped at `max_object_bytes` in total (0: no
/// cap). Throws what ReadObject throws, and std::runtime_error("object needs more than N
/// bytes ...") when the cap is hit.
mrpt::serialization::CSerializable::Ptr guardedReadObject(mrpt::serialization::CArchive& archive,
                                                          std::uint64_t max_object_bytes);

}  // namespace stairmap::io
