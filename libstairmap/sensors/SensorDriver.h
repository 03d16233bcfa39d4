#pragma once
// One MRPT sensor driver (mrpt::hwdrivers::CGenericSensor) created from its INI section, as
// rawlog-grabber does: createSensor(driver), loadConfig(ini, section), initialize(); then one
// step() per turn of the driver loop. Not thread-safe: one thread drives it.
//
// CVelodyneScanner (MRPT 2.5.8, built with libpcap) is stepped through getNextObservation(), which
// is what its doProcess() calls, so that the end of a pcap read once is a clean end of stream
// rather than a printed error and the ssError state. Its pcap is checked first (PcapProbe.h). Its
// replay rate is the driver's: packets as fast as they are read, then pcap_read_full_scan_delay_ms
// (default 100 ms) after each full rotation, i.e. ~10 rotations/s (a VLP-16 at 600 rpm records
// 10/s); pcap_read_fast = true drops the delay.
// Other drivers are stepped with doProcess() + getObservations(); the caller paces them at
// process_rate as rawlog-grabber does.

#include <mrpt/obs/CObservation.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sensors/DriverIni.h"
#include "sensors/PcapProbe.h"

namespace stairmap::sensors {

class SensorDriver {
public:
    /// Creates, configures and initialises the driver (opens the pcap or binds the UDP sockets).
    /// Throws std::runtime_error "<ini> [<section>]: ..." naming the problem: a driver class MRPT
    /// does not know, a key the driver rejects, an unreadable or empty pcap, a failed initialise.
    explicit SensorDriver(const DriverSection& section);
    ~SensorDriver();
    SensorDriver(const SensorDriver&) = delete;
    SensorDriver& operator=(const SensorDriver&) = delete;

    /// One turn of the driver loop: appends the observations it produced to `out`. Returns false
    /// once the stream has ended for good (a pcap read once, at its end). Driver errors (state
    /// ssError, exceptions) are counted in errors() and the stream goes on.
    bool step(std::vector<mrpt::obs::CObservation::Ptr>& out);

    const DriverSection& section() const { return section_; }
    /// What the pcap held, for a pcap replay.
    const std::optional<PcapSummary>& pcap() const { return pcap_; }
    std::size_t errors() const { return errors_; }
    /// e.g. "CVelodyneScanner [LIDAR] replaying capture.pcap (once, recorded rate)".
    std::string describe() const;
    /// True for drivers that pace themselves (CVelodyneScanner); others need process_rate pacing.
    bool selfPaced() const;

private:
    struct Impl;
    DriverSection section_;
    std::optional<PcapSummary> pcap_;
    std::size_t errors_ = 0;
    std::unique_ptr<Impl> impl_;
};

}  // namespace stairmap::sensors
