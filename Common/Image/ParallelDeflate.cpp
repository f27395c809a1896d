#include "Image/ParallelDeflate.h"

#include "HostThreads.h"

#include <algorithm>

#include <zlib.h>

namespace rt
{
namespace
{
/// One piece as raw deflate data: ended by a sync flush unless it is the last (then a final block).
bool deflatePiece(const unsigned char* data, std::size_t length, int level, bool last,
                  std::vector<unsigned char>& out)
{
    z_stream s{};
    if (deflateInit2(&s, level, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        return false;
    // deflateBound covers the data and a final block; a sync flush adds an empty stored block (5 bytes).
    out.resize(deflateBound(&s, static_cast<uLong>(length)) + 16);
    s.next_in = const_cast<unsigned char*>(data);
    s.avail_in = static_cast<uInt>(length);
    s.next_out = out.data();
    s.avail_out = static_cast<uInt>(out.size());
    const int result = deflate(&s, last ? Z_FINISH : Z_SYNC_FLUSH);
    const bool done = last ? result == Z_STREAM_END : result == Z_OK && s.avail_in == 0 && s.avail_out > 0;
    out.resize(s.total_out);
    deflateEnd(&s);
    return done;
}
} // namespace

std::vector<unsigned char> deflateInParts(const unsigned char* data, std::size_t length, int level, int parts)
{
    // Pieces below 64 KiB gain less from a thread than they lose to their own dictionaries.
    constexpr std::size_t kMinPiece = 64 * 1024;
    const std::size_t count =
        std::clamp<std::size_t>(length / kMinPiece, 1, static_cast<std::size_t>(std::max(parts, 1)));
    // Piece i is data[bounds[i], bounds[i + 1]).
    std::vector<std::size_t> bounds(count + 1);
    for (std::size_t i = 0; i < count; ++i)
        bounds[i] = length / count * i;
    bounds[count] = length;
    std::vector<std::vector<unsigned char>> pieces(count);
    std::vector<char> ok(count, 0);
    std::vector<uLong> adlers(count);
    runInParallel(static_cast<int>(count), [&](int part) {
        const auto i = static_cast<std::size_t>(part);
        const std::size_t size = bounds[i + 1] - bounds[i];
        ok[i] = deflatePiece(data + bounds[i], size, level, i + 1 == count, pieces[i]);
        adlers[i] = adler32(adler32(0L, Z_NULL, 0), data + bounds[i], static_cast<uInt>(size));
    });
    if (std::find(ok.begin(), ok.end(), 0) != ok.end())
        return {};
    // The zlib header: deflate with a 32 KiB window (CMF 0x78), and FLG's level field and check bits.
    const int levelField = level <= 1 ? 0 : level <= 5 ? 1 : level == 6 || level == Z_DEFAULT_COMPRESSION ? 2 : 3;
    const unsigned cmf = 0x78;
    unsigned flg = static_cast<unsigned>(levelField) << 6;
    flg += (31 - (cmf * 256 + flg) % 31) % 31;
    std::vector<unsigned char> stream{static_cast<unsigned char>(cmf), static_cast<unsigned char>(flg)};
    uLong adler = adlers[0];
    for (std::size_t i = 0; i < count; ++i)
    {
        stream.insert(stream.end(), pieces[i].begin(), pieces[i].end());
        if (i > 0)
            adler = adler32_combine(adler, adlers[i], static_cast<z_off_t>(bounds[i + 1] - bounds[i]));
    }
    for (int shift = 24; shift >= 0; shift -= 8)
        stream.push_back(static_cast<unsigned char>((adler >> shift) & 0xff));
    return stream;
}
} // namespace rt
