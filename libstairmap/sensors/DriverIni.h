#pragma once
// The sensor sections of a rawlog-grabber INI file, as `stairmap live --sensor F.ini` reads them.
// Every section except [global] is one sensor (rawlog-grabber's rule), e.g.
//   [LIDAR]
//   driver       = CVelodyneScanner   // an mrpt::hwdrivers class implementing CGenericSensor
//   process_rate = 1000               // [Hz] rawlog-grabber's doProcess() rate
//   sensorLabel  = lidar
//   model        = VLP16
//   pcap_input   = capture.pcap       // replay a capture instead of listening on UDP
//   pcap_read_once = true             // end at the end of the file (default false: loop)
//   pcap_read_fast = false            // false: ~recorded rate (pcap_read_full_scan_delay_ms per rotation)
//   pose_x = 0 ... pose_roll = 0      // [m], [deg] sensor pose on the robot
// The driver reads its own keys (loadConfig); this file only reads what stairmap needs to run it.

#include <string>
#include <vector>

namespace stairmap::sensors {

/// One sensor section.
struct DriverSection {
    std::string ini_path;         ///< the INI file, for error messages
    std::string section;          ///< e.g. "LIDAR"
    std::string driver;           ///< e.g. "CVelodyneScanner"
    double process_rate_hz = 0;   ///< [Hz] doProcess() rate; required (> 0) except for CVelodyneScanner
    bool has_pose_keys = false;   ///< any of pose_x .. pose_roll is set in the section
    /// pcap_input resolved to a path that opens from here: as given if it exists relative to the
    /// working directory (rawlog-grabber's rule), else relative to the INI file's folder.
    std::string pcap_input;
    bool pcap_read_once = false;  ///< pcap replay ends at the end of the file
    bool pcap_read_fast = false;  ///< pcap replay as fast as possible
    std::string identity() const { return ini_path + " [" + section + "]"; }
};

/// Reads every sensor section. Throws std::runtime_error "<ini>: ..." if the file is missing or has
/// no sensor section, "<ini> [<section>]: ..." for a section without `driver` or with a bad
/// process_rate.
std::vector<DriverSection> readDriverSections(const std::string& ini_path);

}  // namespace stairmap::sensors
