#include "io/cloud/GzipBuffer.h"

#include <zlib.h>

#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/cloud/GunzipStream.h"

namespace stairmap::io {

namespace {
constexpr int kGzipWindowBits = 15 + 16;  // zlib: +16 selects the gzip wrapper
constexpr std::size_t kChunk = 1 << 16;
}  // namespace

std::string gzipBuffer(const std::string& data, int level) {
    if (level < 1 || level > 9) throw std::invalid_argument("gzip level must be 1..9");
    if (data.size() > kMaxGunzipBytes) throw std::runtime_error("too large to gzip in one buffer");
    z_stream z{};
    if (deflateInit2(&z, level, Z_DEFLATED, kGzipWindowBits, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        throw std::runtime_error("zlib deflateInit2 failed");
    std::string out(deflateBound(&z, static_cast<uLong>(data.size())), '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
    z.avail_in = static_cast<uInt>(data.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = static_cast<uInt>(out.size());
    const int code = deflate(&z, Z_FINISH);  // deflateBound guarantees one call suffices
    const std::size_t written = z.total_out;
    deflateEnd(&z);
    if (code != Z_STREAM_END) throw std::runtime_error("gzip compression failed");
    out.resize(written);
    return out;
}

std::string gunzipBuffer(const std::string& compressed, std::size_t max_bytes) {
    std::istringstream source(compressed, std::ios::binary);
    GunzipStream in(source, max_bytes);
    std::string out;
    std::vector<char> chunk(kChunk);
    while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0)
        out.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    in.finish();
    return out;
}

}  // namespace stairmap::io
