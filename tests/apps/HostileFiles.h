#pragma once
// Builders of hostile input files for the memory-limit tests: gzip bombs (a small .gz that
// inflates to gigabytes) and far-extent clouds. A bomb is built without compressing gigabytes:
// a chunk of repeated bytes is deflated once after a full flush (which resets the compressor),
// so the same compressed bytes stand for every further copy; the gzip trailer's CRC-32 is
// combined arithmetically (crc32_combine).

#include <zlib.h>

#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>

namespace stairmap::test {

namespace detail {
/// Raw deflate of `data` ending with a full flush (or the final block).
inline std::string deflateChunk(z_stream& z, const std::string& data, int flush) {
    std::string out(deflateBound(&z, static_cast<uLong>(data.size())) + 64, '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
    z.avail_in = static_cast<uInt>(data.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = static_cast<uInt>(out.size());
    if (deflate(&z, flush) == Z_STREAM_ERROR || z.avail_in != 0) throw std::runtime_error("deflate failed");
    out.resize(out.size() - z.avail_out);
    return out;
}

inline void putLe32(std::ofstream& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.put(static_cast<char>((v >> (8 * i)) & 0xff));
}
}  // namespace detail

/// Writes a gzip file holding `head` followed by `copies` times `chunk`. Returns the file size.
inline std::size_t writeGzipBomb(const std::string& path, const std::string& head, const std::string& chunk,
                                 std::size_t copies) {
    z_stream z{};
    if (deflateInit2(&z, 9, Z_DEFLATED, -15, 9, Z_DEFAULT_STRATEGY) != Z_OK) throw std::runtime_error("zlib");
    const std::string head_z = detail::deflateChunk(z, head, Z_FULL_FLUSH);
    const std::string chunk_z = detail::deflateChunk(z, chunk, Z_FULL_FLUSH);
    const std::string tail_z = detail::deflateChunk(z, "", Z_FINISH);
    deflateEnd(&z);
    const auto crc_of = [](const std::string& s) {
        return crc32(0, reinterpret_cast<const Bytef*>(s.data()), static_cast<uInt>(s.size()));
    };
    uLong crc = crc_of(head);
    const uLong chunk_crc = crc_of(chunk);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03", 10);  // gzip header, no name, no time
    out << head_z;
    for (std::size_t i = 0; i < copies; ++i) {
        out << chunk_z;
        crc = crc32_combine(crc, chunk_crc, static_cast<z_off_t>(chunk.size()));
    }
    out << tail_z;
    detail::putLe32(out, static_cast<std::uint32_t>(crc));
    detail::putLe32(out, static_cast<std::uint32_t>(head.size() + copies * chunk.size()));  // mod 2^32
    if (!out) throw std::runtime_error("cannot write " + path);
    return static_cast<std::size_t>(out.tellp());
}

}  // namespace stairmap::test
