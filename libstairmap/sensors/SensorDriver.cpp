#include "sensors/SensorDriver.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/hwdrivers/CGenericSensor.h>
#include <mrpt/hwdrivers/CVelodyneScanner.h>

#include <chrono>
#include <stdexcept>
#include <thread>

#include "io/rawlog/MrptErrorText.h"

namespace stairmap::sensors {

using mrpt::hwdrivers::CGenericSensor;
using mrpt::hwdrivers::CVelodyneScanner;

struct SensorDriver::Impl {
    CGenericSensor::Ptr sensor;
    CVelodyneScanner* velodyne = nullptr;  // the same object, when it is a Velodyne
};

namespace {

/// The driver's data port (a `short` in MRPT: ports above 32767 read as negative).
std::uint16_t dataPort() { return std::uint16_t(CVelodyneScanner::VELODYNE_DATA_UDP_PORT); }

CGenericSensor::Ptr createDriver(const DriverSection& s) {
    CGenericSensor::Ptr sensor;
    try {
        sensor = CGenericSensor::createSensorPtr(s.driver);
    } catch (const std::exception& e) {
        throw std::runtime_error(s.identity() + ": driver '" + s.driver + "' could not be created: " + io::mrptErrorText(e));
    }
    if (!sensor) {
        throw std::runtime_error(s.identity() + ": driver '" + s.driver +
                                 "' is not an MRPT sensor class (mrpt::hwdrivers, e.g. CVelodyneScanner)");
    }
    return sensor;
}

/// Checks the capture before the driver sees it (see PcapProbe.h for why).
PcapSummary checkPcap(const DriverSection& s) {
    PcapSummary summary;
    try {
        summary = probePcap(s.pcap_input, dataPort());
    } catch (const std::exception& e) {
        throw std::runtime_error(s.identity() + ": pcap_input " + e.what());
    }
    if (summary.data_packets == 0) {
        throw std::runtime_error(s.identity() + ": pcap_input " + s.pcap_input +
                                 ": holds no complete Velodyne data packet (1206-byte UDP payload to port " +
                                 std::to_string(dataPort()) + ")" +
                                 (summary.truncated ? "; the file is cut short" : ""));
    }
    return summary;
}

}  // namespace

SensorDriver::SensorDriver(const DriverSection& section)
    : section_(section), impl_(std::make_unique<Impl>()) {
    impl_->sensor = createDriver(section_);
    impl_->velodyne = dynamic_cast<CVelodyneScanner*>(impl_->sensor.get());
    try {
        const mrpt::config::CConfigFile cfg(section_.ini_path);
        impl_->sensor->loadConfig(cfg, section_.section);
    } catch (const std::exception& e) {
        throw std::runtime_error(section_.identity() + ": " + section_.driver + " rejected its configuration: " + io::mrptErrorText(e));
    }
    if (impl_->velodyne) {
        impl_->velodyne->setPCAPVerbosity(false);
        if (!section_.pcap_input.empty()) {
            pcap_ = checkPcap(section_);
            impl_->velodyne->setPCAPInputFile(section_.pcap_input);
        }
    }
    try {
        impl_->sensor->initialize();
    } catch (const std::exception& e) {
        throw std::runtime_error(section_.identity() + ": " + section_.driver + " failed to initialise: " + io::mrptErrorText(e));
    }
}

SensorDriver::~SensorDriver() = default;

bool SensorDriver::selfPaced() const { return impl_->velodyne != nullptr; }

std::string SensorDriver::describe() const {
    std::string d = section_.driver + " [" + section_.section + "]";
    if (!pcap_) return d + (impl_->velodyne ? " on live UDP port " + std::to_string(dataPort()) : "");
    return d + " replaying " + section_.pcap_input + " (" + (section_.pcap_read_once ? "once" : "looped") + ", " +
           (section_.pcap_read_fast ? "fast" : "recorded rate") + ")";
}

bool SensorDriver::step(std::vector<mrpt::obs::CObservation::Ptr>& out) {
    if (impl_->velodyne) {
        mrpt::obs::CObservationVelodyneScan::Ptr scan;
        mrpt::obs::CObservationGPS::Ptr gps;
        if (!impl_->velodyne->getNextObservation(scan, gps)) {
            if (pcap_) return false;  // end of a pcap read once (or its read failed for good)
            ++errors_;                // a socket error: the driver printed it; retry shortly
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            return true;
        }
        if (scan) out.push_back(scan);
        if (gps) out.push_back(gps);
        return true;
    }
    try {
        impl_->sensor->doProcess();
        for (const auto& [stamp, object] : impl_->sensor->getObservations()) {
            if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object)) out.push_back(obs);
        }
    } catch (const std::exception&) {
        ++errors_;
    }
    if (impl_->sensor->getState() == CGenericSensor::ssError) ++errors_;
    return true;
}

}  // namespace stairmap::sensors
