#include "io/rawlog/GuardedReadObject.h"

#include <csetjmp>
#include <csignal>
#include <optional>
#include <stdexcept>

#include "io/rawlog/AddressSpaceGuard.h"

namespace stairmap::io {
namespace {

sigjmp_buf* g_fault_jump = nullptr;  // set only while guardedReadObject runs

void onFault(int sig) {
    if (g_fault_jump) siglongjmp(*g_fault_jump, sig);
    std::signal(sig, SIG_DFL);  // not ours: behave as if we were never installed
    std::raise(sig);
}

// Installs onFault for SIGSEGV and SIGBUS; restores the previous handlers on destruction.
class FaultHandlers {
public:
    FaultHandlers() {
        struct sigaction sa {};
        sa.sa_handler = onFault;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_NODEFER;
        sigaction(SIGSEGV, &sa, &old_segv_);
        sigaction(SIGBUS, &sa, &old_bus_);
    }
    ~FaultHandlers() {
        sigaction(SIGSEGV, &old_segv_, nullptr);
        sigaction(SIGBUS, &old_bus_, nullptr);
    }

private:
    struct sigaction old_segv_ {};
    struct sigaction old_bus_ {};
};

}  // namespace

mrpt::serialization::CSerializable::Ptr guardedReadObject(mrpt::serialization::CArchive& archive,
                                                          std::uint64_t headroom_bytes) {
    std::optional<AddressSpaceGuard> memory_cap;
    memory_cap.emplace(headroom_bytes);
    FaultHandlers handlers;
    sigjmp_buf jump;
    mrpt::serialization::CSerializable::Ptr object;
    if (sigsetjmp(jump, 1) != 0) {  // came back from a fault inside ReadObject
        g_fault_jump = nullptr;
        memory_cap.reset();
        throw std::runtime_error(
            "memory fault while deserializing (corrupt size field in the data?)");
    }
    g_fault_jump = &jump;
    try {
        object = archive.ReadObject();
    } catch (...) {
        g_fault_jump = nullptr;
        throw;
    }
    g_fault_jump = nullptr;
    return object;
}

}  // namespace stairmap::io
