#pragma once
// Test helper: what a rendered picture shows, counted in pixels (frames of `stairmap view`, in a
// window or headless). mrpt::img::CImage stores BGR; colours here are given as RGB.

#include <mrpt/img/CImage.h>

#include <cstdlib>
#include <utility>
#include <vector>

namespace stairmap::test {

/// Whether pixel (x, y) is within `tolerance` per channel of `rgb`.
inline bool pixelIs(const mrpt::img::CImage& img, int x, int y, const unsigned char* rgb,
                    int tolerance = 40) {
    return std::abs(int(*img(x, y, 2)) - rgb[0]) < tolerance &&
           std::abs(int(*img(x, y, 1)) - rgb[1]) < tolerance &&
           std::abs(int(*img(x, y, 0)) - rgb[2]) < tolerance;
}

/// Pixels within `tolerance` per channel of `rgb`.
inline std::size_t pixelsNear(const mrpt::img::CImage& img, const unsigned char* rgb,
                              int tolerance = 40) {
    std::size_t n = 0;
    for (int y = 0; y < static_cast<int>(img.getHeight()); ++y)
        for (int x = 0; x < static_cast<int>(img.getWidth()); ++x) n += pixelIs(img, x, y, rgb, tolerance);
    return n;
}

/// Fraction of pixels whose colour differs (any channel by > 8) between two same-size images.
inline double differingFraction(const mrpt::img::CImage& a, const mrpt::img::CImage& b) {
    std::size_t diff = 0;
    for (int y = 0; y < static_cast<int>(a.getHeight()); ++y)
        for (int x = 0; x < static_cast<int>(a.getWidth()); ++x)
            for (unsigned c = 0; c < 3; ++c)
                if (std::abs(int(*a(x, y, c)) - int(*b(x, y, c))) > 8) {
                    ++diff;
                    break;
                }
    return double(diff) / (a.getWidth() * a.getHeight());
}

/// The pixel of `rgb` with the most pixels of that colour in its 7x7 neighbourhood (inside a
/// drawn edge, not at its anti-aliased border); (-1, -1) if there is none.
inline std::pair<int, int> densestPixel(const mrpt::img::CImage& img, const unsigned char* rgb) {
    const int w = static_cast<int>(img.getWidth()), h = static_cast<int>(img.getHeight());
    std::vector<char> is(std::size_t(w) * h, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) is[std::size_t(y) * w + x] = pixelIs(img, x, y, rgb);
    std::pair<int, int> best{-1, -1};
    int best_count = 0;
    for (int y = 3; y < h - 3; ++y)
        for (int x = 3; x < w - 3; ++x) {
            if (!is[std::size_t(y) * w + x]) continue;
            int count = 0;
            for (int dy = -3; dy <= 3; ++dy)
                for (int dx = -3; dx <= 3; ++dx) count += is[std::size_t(y + dy) * w + x + dx];
            if (count > best_count) best_count = count, best = {x, y};
        }
    return best;
}

}  // namespace stairmap::test
