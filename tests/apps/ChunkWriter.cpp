// Test helper program: plays a writer that appends a log to a file in random-sized byte chunks at
// a fixed rate, flushing in the middle of objects as real recorders do, as a separate process.
//   stairmap_test_chunk_writer SRC DST PERIOD_MS MIN_BYTES MAX_BYTES SEED LIMIT_BYTES [SRC2 DST2]
// SRC may be gzip-compressed (read with zlib; DST gets the plain bytes). LIMIT_BYTES > 0 stops
// after that many bytes of SRC (a writer that stalls). SRC2/DST2 (e.g. the TUM trajectory) are
// appended in step: after each chunk, the same fraction of SRC2 as of SRC has been written.
// Exits 0 when done, 2 on bad arguments or I/O errors.
#include <zlib.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <thread>

namespace {

bool readAll(const char* path, std::string& out) {
    gzFile in = gzopen(path, "rb");  // reads plain files too
    if (!in) return false;
    char buf[65536];
    int n = 0;
    while ((n = gzread(in, buf, sizeof buf)) > 0) out.append(buf, static_cast<std::size_t>(n));
    gzclose(in);
    return n == 0;
}

bool appendBytes(const char* path, const std::string& data, std::size_t from, std::size_t to) {
    if (to <= from) return true;
    std::FILE* f = std::fopen(path, "ab");
    if (!f) return false;
    const bool ok = std::fwrite(data.data() + from, 1, to - from, f) == to - from;
    return std::fclose(f) == 0 && ok;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 8 && argc != 10) {
        std::fprintf(stderr, "usage: %s SRC DST PERIOD_MS MIN MAX SEED LIMIT [SRC2 DST2]\n", argv[0]);
        return 2;
    }
    std::string data, data2;
    if (!readAll(argv[1], data) || (argc == 10 && !readAll(argv[8], data2))) {
        std::fprintf(stderr, "cannot read the source files\n");
        return 2;
    }
    const auto period = std::chrono::milliseconds(std::atol(argv[3]));
    const std::size_t min_bytes = std::strtoul(argv[4], nullptr, 10);
    const std::size_t max_bytes = std::max(min_bytes, std::strtoul(argv[5], nullptr, 10));
    std::mt19937 rng(static_cast<unsigned>(std::atol(argv[6])));
    const std::size_t limit = std::strtoul(argv[7], nullptr, 10);
    const std::size_t end = limit > 0 ? std::min(limit, data.size()) : data.size();
    std::uniform_int_distribution<std::size_t> chunk(min_bytes, max_bytes);
    std::size_t done = 0, done2 = 0;
    while (done < end) {
        const std::size_t next = std::min(end, done + chunk(rng));
        if (!appendBytes(argv[2], data, done, next)) return 2;
        done = next;
        if (argc == 10) {
            const std::size_t next2 = data2.size() * done / data.size();
            if (!appendBytes(argv[9], data2, done2, next2)) return 2;
            done2 = next2;
        }
        std::this_thread::sleep_for(period);
    }
    return 0;
}
