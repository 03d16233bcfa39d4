#pragma once
// Reading one object from an MRPT archive so that corrupt data cannot take the process down.
//
// MRPT's deserializers resize containers to sizes read from the file before reading the data.
// A corrupt size asks for gigabytes: Linux grants it and later kills the process while the
// vector is zero-filled, or (under a memory cap) MRPT's aligned allocator returns null and the
// fill segfaults. So while one object is read we (1) cap the address space growth
// (AddressSpaceGuard) and (2) turn SIGSEGV/SIGBUS raised inside the deserializer into an
// exception. After such a fault the archive must not be used again (the reader stops there; the
// half-built object is leaked). Process-wide signal handlers are swapped in for the duration of
// the call: meant for single-threaded reading.

#include <mrpt/serialization/CArchive.h>

#include <cstdint>

namespace stairmap::io {

/// archive.ReadObject() under the guards above. Throws what ReadObject throws, and
/// std::runtime_error("memory fault while deserializing ...") after a caught fault.
/// `headroom_bytes` = address space the object may take (0: no cap, faults still caught).
mrpt::serialization::CSerializable::Ptr guardedReadObject(mrpt::serialization::CArchive& archive,
                                                          std::uint64_t headroom_bytes);

}  // namespace stairmap::io
