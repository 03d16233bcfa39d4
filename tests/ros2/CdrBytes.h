#pragma once
// Test helper: CDR bytes built by hand (little-endian plain CDR, XCDR1: primitives aligned to
// their size, counted from the end of the 4-byte encapsulation header), independent of idlc and
// Cyclone, to check what goes on the wire; and a DDS round trip (sample -> bytes, bytes ->
// sample) through a writer and a reader on one participant.

#include <dds/dds.h>
#include <dds/ddsi/ddsi_serdata.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace stairmap::test {

class CdrBytes {
public:
    CdrBytes() : bytes_{0x00, 0x01, 0x00, 0x00} {}  // CDR_LE encapsulation, options 0
    CdrBytes& u8(std::uint8_t v) { return raw(&v, 1, 1); }
    CdrBytes& boolean(bool v) { return u8(v ? 1 : 0); }
    CdrBytes& u32(std::uint32_t v) { return raw(&v, 4, 4); }
    CdrBytes& i32(std::int32_t v) { return raw(&v, 4, 4); }
    CdrBytes& f32(float v) { return raw(&v, 4, 4); }
    CdrBytes& f64(double v) { return raw(&v, 8, 8); }
    CdrBytes& str(const std::string& s) {
        u32(static_cast<std::uint32_t>(s.size() + 1));
        for (char c : s) u8(static_cast<std::uint8_t>(c));
        return u8(0);
    }
    CdrBytes& octets(const std::vector<std::uint8_t>& v) {
        u32(static_cast<std::uint32_t>(v.size()));
        for (auto b : v) u8(b);
        return *this;
    }
    const std::vector<std::uint8_t>& bytes() const { return bytes_; }

private:
    CdrBytes& raw(const void* p, std::size_t n, std::size_t align) {
        while ((bytes_.size() - 4) % align != 0) bytes_.push_back(0);
        const auto* b = static_cast<const std::uint8_t*>(p);
        bytes_.insert(bytes_.end(), b, b + n);  // the test hosts are little-endian
        return *this;
    }
    std::vector<std::uint8_t> bytes_;
};

/// One writer and one reader (reliable, keep-all) of a topic on a private participant.
class CdrRoundTrip {
public:
    CdrRoundTrip(const dds_topic_descriptor_t* descriptor, const std::string& topic_name);
    ~CdrRoundTrip();
    /// Writes `sample`; returns the serialized bytes the reader got (header included).
    std::vector<std::uint8_t> bytesOf(const void* sample);
    /// Writes `bytes` as serialized data; the reader takes it as a sample into `out` (a
    /// zero-initialised struct of the topic's type; free with dds_sample_free(..., DDS_FREE_CONTENTS)).
    bool sampleOf(const std::vector<std::uint8_t>& bytes, void* out);

private:
    dds_entity_t participant_, topic_, writer_, reader_;
    const ddsi_sertype* sertype_ = nullptr;
};

}  // namespace stairmap::test
