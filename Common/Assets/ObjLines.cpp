#include "Assets/ObjLines.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt
{
namespace
{
/// A finite number written in full (no trailing characters), or nothing.
std::optional<double> finiteNumber(const std::string& word)
{
    // strtod rather than from_chars: libstdc++'s double from_chars is recent, strtod takes what OBJ writers
    // print (1e-7, .5, +2). It also takes "nan" and "inf", which are refused below.
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (word.empty() || end != word.c_str() + word.size() || !std::isfinite(value))
        return std::nullopt; // an overflow is HUGE_VAL, so refused as not finite; an underflow reads as about 0

    return value;
}

/// A face vertex's index list: "v", "v/t", "v//n" or "v/t/n".
struct FaceIndices
{
    std::string v, t, n;
};

FaceIndices splitFaceVertex(const std::string& word)
{
    FaceIndices out;
    const std::size_t a = word.find('/');
    out.v = word.substr(0, a);
    if (a == std::string::npos)
        return out;
    const std::size_t b = word.find('/', a + 1);
    out.t = word.substr(a + 1, b == std::string::npos ? std::string::npos : b - a - 1);
    if (b != std::string::npos)
        out.n = word.substr(b + 1);
    return out;
}

class Scanner
{
public:
    explicit Scanner(const std::filesystem::path& file) : m_file(file) {}

    ObjLines run()
    {
        std::ifstream in(m_file, std::ios::binary);
        if (!in)
            fail(0, "cannot be read");
        std::string line;
        for (m_line = 1; std::getline(in, line); ++m_line)
            statement(line);
        // Positive indices may point forward in the file: checked once every vertex is counted, by the largest
        // of each kind (one per kind kept, not one per face vertex: meshes have millions).
        for (const Largest& l : m_largest)
            if (l.line > 0)
                checkPositive(l.line, l.written, l.index, l.kind);
        return std::move(m_result);
    }

private:
    /// The largest positive index of a kind so far, where it was and how it was written.
    struct Largest
    {
        std::size_t line = 0; // 0: none yet
        std::string written;
        long long index = 0;
        char kind = 'v'; // 'v', 't' or 'n'
    };

    [[noreturn]] void fail(std::size_t line, const std::string& problem) const
    {
        if (line == 0)
            throw AssetError(fmt::format("malformed OBJ '{}': {}", m_file.string(), problem));
        throw AssetError(fmt::format("malformed OBJ '{}': line {}: {}", m_file.string(), line, problem));
    }

    void statement(const std::string& raw)
    {
        std::istringstream words(raw.substr(0, raw.find('#')));
        std::string keyword;
        if (!(words >> keyword))
            return;
        std::vector<std::string> args;
        for (std::string w; words >> w;)
            args.push_back(w);
        if (keyword == "v")
            vertex(args);
        else if (keyword == "vn")
        {
            numbers("normal", args, 3, 3, "3");
            ++m_result.normals;
        }
        else if (keyword == "vt")
        {
            numbers("texture coordinate", args, 1, 3, "1 to 3");
            ++m_result.texcoords;
        }
        else if (keyword == "f")
            face(args);
    }

    /// The statement's numbers, `fewest` to `most` of them (`needed` words the rule for the message).
    std::vector<double> numbers(const char* what, const std::vector<std::string>& args, std::size_t fewest,
                                std::size_t most, const std::string& needed) const
    {
        std::vector<double> values;
        for (const std::string& a : args)
        {
            const auto value = finiteNumber(a);
            if (!value)
                fail(m_line, fmt::format("a {}'s number '{}' is not a finite number", what, a));
            values.push_back(*value);
        }
        if (values.size() < fewest || values.size() > most)
            fail(m_line, fmt::format("a {} with {} number{} ({} needed)", what, values.size(),
                                     values.size() == 1 ? "" : "s", needed));
        return values;
    }

    void vertex(const std::vector<std::string>& args)
    {
        const char* needed = "3, 4 with w, or 6 with a colour";
        const std::vector<double> xyz = numbers("vertex", args, 3, 6, needed);
        if (xyz.size() == 5)
            fail(m_line, fmt::format("a vertex with 5 numbers ({} needed)", needed));
        m_result.positions.emplace_back(xyz[0], xyz[1], xyz[2]);
    }

    void face(const std::vector<std::string>& args)
    {
        if (args.size() < 3)
            fail(m_line, fmt::format("a face with {} vertices (at least 3 needed)", args.size()));
        for (const std::string& a : args)
        {
            const FaceIndices f = splitFaceVertex(a);
            index(f.v, 'v', true);
            index(f.t, 't', false);
            index(f.n, 'n', false);
        }
    }

    std::size_t countOf(char kind) const
    {
        return kind == 'v' ? m_result.positions.size() : kind == 't' ? m_result.texcoords : m_result.normals;
    }

    static const char* nameOf(char kind)
    {
        return kind == 'v' ? "vertex" : kind == 't' ? "texture coordinate" : "normal";
    }

    static std::string countedName(char kind, std::size_t count)
    {
        if (count == 1)
            return nameOf(kind);
        return kind == 'v' ? "vertices" : std::string(nameOf(kind)) + "s";
    }

    void index(const std::string& written, char kind, bool required)
    {
        if (written.empty())
        {
            if (required)
                fail(m_line, "a face vertex without a vertex index");
            return;
        }
        long long value = 0;
        const auto [end, ec] = std::from_chars(written.data(), written.data() + written.size(), value);
        if (ec != std::errc() || end != written.data() + written.size())
            fail(m_line, fmt::format("{} index '{}' is not an integer", nameOf(kind), written));
        if (value == 0)
            fail(m_line, fmt::format("{} index 0 (OBJ counts from 1)", nameOf(kind)));
        if (value < 0)
        {
            // Relative: -1 is the latest of its kind before this line.
            if (static_cast<unsigned long long>(-value) > countOf(kind))
                fail(m_line, fmt::format("{} index {} reaches before the first {} ({} defined so far)", nameOf(kind),
                                         written, nameOf(kind), countOf(kind)));
            return;
        }
        Largest& largest = m_largest[kind == 'v' ? 0 : kind == 't' ? 1 : 2];
        if (value > largest.index)
            largest = {m_line, written, value, kind};
    }

    void checkPositive(std::size_t line, const std::string& written, long long value, char kind) const
    {
        if (static_cast<unsigned long long>(value) > countOf(kind))
            fail(line, fmt::format("{} index {} is out of range: the file has {} {}", nameOf(kind), written,
                                   countOf(kind), countedName(kind, countOf(kind))));
    }

    std::filesystem::path m_file;
    std::size_t m_line = 0;
    ObjLines m_result;
    Largest m_largest[3]; // vertex, texture coordinate, normal
};
} // namespace

ObjLines scanObjLines(const std::filesystem::path& file) { return Scanner(file).run(); }
} // namespace rt
