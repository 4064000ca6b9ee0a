// SPDX-License-Identifier: GPL-2.0-or-later
// sample_format.cpp - format one sampler record as a line of halsampler output.
#include "sample_format.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace hal {

namespace {

template <typename Int>
char* put_int(char* p, Int v)
{
    return std::to_chars(p, p + 24, v).ptr;
}

// Two decimal digits of 0..99.
constexpr char digit_pairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// "%f" of a finite |v| < 2^43 (about 8.8e12), or nullptr for other values. Exact integer
// arithmetic: |v| = m * 2^-k with a 53-bit m and k >= 10, so m * 10^6 fits in 73 bits and
// round(m * 10^6 / 2^k), ties to even as printf rounds them, in 63. Several times faster
// than to_chars, which stays the general case (halsampler prints 8 values a sample).
char* put_small_float(char* p, double v)
{
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof(bits));
    int biased = static_cast<int>((bits >> 52) & 0x7ff);
    if (biased > 1065)  // |v| >= 2^43, infinities, NaNs
        return nullptr;
    uint64_t q = 0;  // round(|v| * 10^6); subnormals (biased 0) round to 0
    int k = 1075 - biased;
    if (biased != 0 && k < 100) {  // from k = 100 on, m * 10^6 < 2^73 is below half of 2^k
        unsigned __int128 x = static_cast<unsigned __int128>((bits & ((1ull << 52) - 1)) | (1ull << 52)) * 1000000u;
        unsigned __int128 half = static_cast<unsigned __int128>(1) << (k - 1);
        unsigned __int128 r = x & ((half << 1) - 1);
        q = static_cast<uint64_t>(x >> k);
        if (r > half || (r == half && (q & 1)))
            q++;
    }
    if (bits >> 63)
        *p++ = '-';
    uint64_t whole = q / 1000000;
    if (whole == 0)
        *p++ = '0';
    else
        p = std::to_chars(p, p + 24, whole).ptr;
    *p++ = '.';
    uint32_t f = static_cast<uint32_t>(q % 1000000);
    std::memcpy(p, digit_pairs + 2 * (f / 10000), 2);
    std::memcpy(p + 2, digit_pairs + 2 * (f / 100 % 100), 2);
    std::memcpy(p + 4, digit_pairs + 2 * (f % 100), 2);
    return p + 6;
}

// "%f": six decimals, correctly rounded, as glibc's printf does it. to_chars spells
// infinities and NaNs as printf does too ("inf", "-inf", "nan", "-nan"); they are
// written here anyway so the bytes do not hang on that.
char* put_float(char* p, double v)
{
    if (!std::isfinite(v)) {
        const char* s = std::isnan(v) ? (std::signbit(v) ? "-nan" : "nan")
                                      : (v < 0 ? "-inf" : "inf");
        size_t n = std::strlen(s);
        std::memcpy(p, s, n);
        return p + n;
    }
    if (char* q = put_small_float(p, v))
        return q;
    return std::to_chars(p, p + 330, v, std::chars_format::fixed, 6).ptr;
}

}  // namespace

char* format_sample_to(char* p, std::string_view cfg, const hal_fifo_value* rec, bool tag)
{
    if (tag) {
        p = put_int(p, static_cast<int32_t>(rec[HAL_FIFO_REC_SAMPLE].s));
        *p++ = ' ';
    }
    const hal_fifo_value* v = rec + HAL_FIFO_REC_HDR_WORDS;
    for (size_t m = 0; m < cfg.size(); m++) {
        switch (hal_fifo_type_of(cfg[m])) {
        case HAL_FIFO_FLOAT: p = put_float(p, v[m].f); break;
        case HAL_FIFO_BIT: *p++ = v[m].u ? '1' : '0'; break;
        case HAL_FIFO_S32: p = put_int(p, static_cast<int32_t>(v[m].s)); break;
        case HAL_FIFO_U32: p = put_int(p, static_cast<uint32_t>(v[m].u)); break;
        case HAL_FIFO_S64: p = put_int(p, static_cast<int64_t>(v[m].s)); break;
        case HAL_FIFO_U64: p = put_int(p, static_cast<uint64_t>(v[m].u)); break;
        default: *p++ = '?'; break;
        }
        *p++ = ' ';
    }
    *p++ = '\n';
    return p;
}

std::string format_sample(std::string_view cfg, const hal_fifo_value* rec, bool tag)
{
    std::string line(max_sample_line, '\0');
    char* end = format_sample_to(line.data(), cfg, rec, tag);
    line.resize(static_cast<size_t>(end - line.data()));
    return line;
}

}  // namespace hal
