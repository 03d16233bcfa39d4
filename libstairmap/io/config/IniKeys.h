#pragma once
// Which sections and keys an INI file may hold, learnt from the loaders themselves: a KeyRecorder
// wraps the config a loader reads and notes every (section, key) it asks for. Running a loader on
// an empty config gives its complete table (the loaders read every key they know unconditionally),
// so no list of valid keys is written twice. checkIniKeys then refuses any line of a file outside
// the table, naming file, line, section and key and listing the valid keys of that section.

#include <mrpt/config/CConfigFileBase.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "io/config/IniSyntax.h"

namespace stairmap::io {

/// Lower-cased section name -> lower-cased keys.
using IniKeys = std::map<std::string, std::set<std::string>>;

/// A read-only view of another config that records every key read through it. Reads are
/// delegated unchanged; writing throws std::logic_error.
class KeyRecorder : public mrpt::config::CConfigFileBase {
  public:
    explicit KeyRecorder(const mrpt::config::CConfigFileBase& inner) : inner_(inner) {}

    const IniKeys& keys() const { return keys_; }

    void getAllSections(std::vector<std::string>& sections) const override;
    void getAllKeys(const std::string& section, std::vector<std::string>& keys) const override;
    void clear() override;

  protected:
    void writeString(const std::string& section, const std::string& name,
                     const std::string& str) override;
    std::string readString(const std::string& section, const std::string& name,
                           const std::string& default_str, bool fail_if_not_found) const override;

  private:
    const mrpt::config::CConfigFileBase& inner_;
    mutable IniKeys keys_;
};

/// Throws std::runtime_error for the first line of `lines` whose section or key is not in
/// `known`: "<source>:<line>: unknown section [x] (did you mean [y]?); valid sections: ..." or
/// "<source>:<line>: [s] key: unknown key (did you mean z?); valid keys of [s]: ...".
void checkIniKeys(const std::vector<IniLine>& lines, const IniKeys& known,
                  const std::string& source);

}  // namespace stairmap::io
