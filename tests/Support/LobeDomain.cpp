#include "Support/LobeDomain.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace rt::test
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kEdgeTolerance = 1e-4; // as CapDomain: a sampler's rounding at a hemisphere cap's rim

bool onSide(double z, Side side)
{
    return side == Side::Upper ? z >= 0.0 : z < 0.0;
}

/// Cell integrals of a density times `samples`, and the other cell's count: the samples they leave out.
std::vector<double> countsWithOtherCell(std::vector<double> counts, long samples)
{
    double total = 0.0;
    for (double& c : counts)
    {
        c *= double(samples);
        total += c;
    }
    counts.push_back(std::max(0.0, double(samples) - total));
    return counts;
}

double sum(const std::vector<double>& values)
{
    double total = 0.0;
    for (double v : values)
        total += v;
    return total;
}
} // namespace

// Newton on the Legendre recurrence (Press et al., Numerical Recipes §4.6), mapped from [-1, 1].
void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w)
{
    x.assign(n, 0.0);
    w.assign(n, 0.0);
    for (int i = 0; i < n; ++i)
    {
        double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration)
        {
            double p0 = 1.0, p1 = 0.0;
            for (int j = 1; j <= n; ++j)
            {
                const double p2 = p1;
                p1 = p0;
                p0 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p2) / j;
            }
            dp = n * (z * p0 - p1) / (z * z - 1.0);
            const double previous = z;
            z -= p0 / dp;
            if (std::fabs(z - previous) < 1e-15)
                break;
        }
        x[i] = 0.5 * (1.0 - z);
        w[i] = 1.0 / ((1.0 - z * z) * dp * dp);
    }
}

LobeDomain::LobeDomain(std::vector<LobeCap> caps, std::vector<Crease> creases)
{
    m_creases.push_back([](const glm::dvec3& d) { return d.z; });
    for (Crease& crease : creases)
        m_creases.push_back(std::move(crease));
    bool used[2] = {false, false};
    for (const LobeCap& spec : caps)
    {
        Cap cap;
        cap.spec = spec;
        // An axis along z is the pole exactly: one rounded off it would cut the horizon through its rows.
        const bool pole = spec.axis.x == 0.0 && spec.axis.y == 0.0;
        cap.spec.axis =
            pole ? glm::dvec3(0.0, 0.0, spec.axis.z > 0.0 ? 1.0 : -1.0) : glm::normalize(spec.axis);
        const int sideIndex = spec.side == Side::Upper ? 0 : 1;
        if (used[sideIndex])
            throw std::invalid_argument("LobeDomain: two caps on one side");
        used[sideIndex] = true;
        const glm::dvec3& a = cap.spec.axis;
        if (pole && (a.z > 0.0) != (spec.side == Side::Upper))
            throw std::invalid_argument("LobeDomain: a pole's cap must be on the pole's side");
        // A pole's cap ends at the horizon, so the density's jump there falls between rows; any other axis
        // spans the whole sphere, and its radial lines are cut where they cross the horizon.
        cap.extent = pole ? 1.0 : 2.0;
        const glm::dvec3 helper = std::fabs(a.x) > 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
        cap.u = glm::normalize(glm::cross(helper, a));
        cap.v = glm::cross(a, cap.u);
        cap.tExtent = 0.0;
        cap.firstCell = m_cellCount;
        m_caps.push_back(cap);
        m_caps.back().tExtent = mapped(m_caps.back(), cap.extent);
        m_cellCount += spec.rows * spec.columns;
    }
}

double LobeDomain::mapped(const Cap& cap, double s) const
{
    return cap.spec.scale > 0.0 ? std::log1p(s / cap.spec.scale) : s;
}

int LobeDomain::cell(const glm::dvec3& d) const
{
    const Side side = d.z >= 0.0 ? Side::Upper : Side::Lower;
    const Cap* cap = nullptr;
    for (const Cap& c : m_caps)
        if (c.spec.side == side)
            cap = &c;
    if (!cap)
        return otherCell();
    // 1 - cos from the sine near the axis (as CapDomain: a lobe 1e-3 wide is below cos's resolution).
    const glm::dvec3& a = cap->spec.axis;
    const double length2 = glm::dot(d, d);
    const double c = glm::dot(d, a) / std::sqrt(length2);
    const glm::dvec3 x = glm::cross(d, a);
    const double s = c > 0.0 ? glm::dot(x, x) / length2 / (1.0 + c) : 1.0 - c;
    if (s > cap->extent * (1.0 + kEdgeTolerance))
        return otherCell();
    const int rows = cap->spec.rows, columns = cap->spec.columns;
    const int row = std::clamp(static_cast<int>(mapped(*cap, s) / cap->tExtent * rows), 0, rows - 1);
    double phi = std::atan2(glm::dot(d, cap->v), glm::dot(d, cap->u));
    if (phi < 0.0)
        phi += 2.0 * kPi;
    const int column = std::clamp(static_cast<int>(phi / (2.0 * kPi) * columns), 0, columns - 1);
    return cap->firstCell + row * columns + column;
}

void LobeDomain::cuts(const Cap& cap, const glm::dvec3& e, std::vector<double>& roots) const
{
    roots.clear();
    const int samples = cap.spec.rows; // a crease crossing a line twice within a row is missed: a sliver
    double value[2];
    for (const Crease& g : m_creases)
    {
        value[0] = g(pointAt(cap, e, 0.0));
        for (int k = 0; k < samples; ++k)
        {
            value[1] = g(pointAt(cap, e, double(k + 1) / samples));
            if ((value[0] < 0.0) != (value[1] < 0.0))
            {
                double lo = double(k) / samples, hi = double(k + 1) / samples;
                const bool loNegative = value[0] < 0.0;
                for (int iteration = 0; iteration < 32; ++iteration) // to 2^-32 of a row
                {
                    const double mid = 0.5 * (lo + hi);
                    ((g(pointAt(cap, e, mid)) < 0.0) == loNegative ? lo : hi) = mid;
                }
                roots.push_back(0.5 * (lo + hi));
            }
            value[0] = value[1];
        }
    }
    std::sort(roots.begin(), roots.end());
}

std::vector<double> LobeDomain::cellIntegrals(const std::function<double(const glm::dvec3&)>& f,
                                              int subdivisions) const
{
    std::vector<double> integrals(static_cast<std::size_t>(m_cellCount), 0.0);
    const int n = subdivisions;
    // Gauss-Legendre in both coordinates: each piece of a radial line between cuts is smooth, and so is the
    // integral of a radial line across a part of a column where the cuts move little.
    std::vector<double> node, weight;
    gaussLegendre(n, node, weight);
    for (const Cap& cap : m_caps)
    {
        const int rows = cap.spec.rows, columns = cap.spec.columns;
        const double columnWidth = 2.0 * kPi / columns;
        auto radial = [&](double phi) { return std::cos(phi) * cap.u + std::sin(phi) * cap.v; };
        // Cuts that keep their number and move by at most a quarter row between two azimuths.
        auto close = [&](const std::vector<double>& a, const std::vector<double>& b) {
            if (a.size() != b.size())
                return false;
            for (std::size_t k = 0; k < a.size(); ++k)
                if (std::fabs(a[k] - b[k]) > 0.25 / rows)
                    return false;
            return true;
        };
        std::vector<std::pair<double, double>> parts;
        std::vector<double> lineCuts, ends;
        for (int column = 0; column < columns; ++column)
        {
            // Where a crease passes near the axis at a small angle to the radial lines (a lobe just above the
            // horizon), its cut sweeps along them within a fraction of a degree of azimuth: the column is
            // halved there, down to 1/32 of it, until the cuts are close across each part and its middle.
            parts.clear();
            std::function<void(double, double, const std::vector<double>&, const std::vector<double>&, int)>
                refine = [&](double phi0, double phi1, const std::vector<double>& cuts0,
                             const std::vector<double>& cuts1, int depth) {
                    const double phiMid = 0.5 * (phi0 + phi1);
                    std::vector<double> cutsMid;
                    cuts(cap, radial(phiMid), cutsMid);
                    if (depth >= 5 || (close(cuts0, cutsMid) && close(cutsMid, cuts1)))
                    {
                        parts.emplace_back(phi0, phi1);
                        return;
                    }
                    refine(phi0, phiMid, cuts0, cutsMid, depth + 1);
                    refine(phiMid, phi1, cutsMid, cuts1, depth + 1);
                };
            const double phiStart = column * columnWidth, phiEnd = (column + 1) * columnWidth;
            std::vector<double> cutsStart, cutsEnd;
            cuts(cap, radial(phiStart), cutsStart);
            cuts(cap, radial(phiEnd), cutsEnd);
            refine(phiStart, phiEnd, cutsStart, cutsEnd, 0);
            for (const auto& [phi0, phi1] : parts)
                for (int j = 0; j < n; ++j)
                {
                    const glm::dvec3 e = radial(phi0 + node[j] * (phi1 - phi0));
                    const double dPhi = weight[j] * (phi1 - phi0);
                    cuts(cap, e, lineCuts);
                    for (int row = 0; row < rows; ++row)
                    {
                        ends.assign(1, double(row) / rows);
                        for (double t : lineCuts)
                            if (t > ends.front() && t < double(row + 1) / rows)
                                ends.push_back(t);
                        ends.push_back(double(row + 1) / rows);
                        double sum = 0.0;
                        for (std::size_t piece = 0; piece + 1 < ends.size(); ++piece)
                        {
                            const double t0 = ends[piece], t1 = ends[piece + 1];
                            if (!onSide(pointAt(cap, e, 0.5 * (t0 + t1)).z, cap.spec.side))
                                continue; // the whole piece lies on the other side
                            for (int i = 0; i < n; ++i)
                            {
                                double s, dsdT;
                                sAt(cap, t0 + node[i] * (t1 - t0), s, dsdT);
                                const double cosTheta = 1.0 - s;
                                const double sinTheta = std::sqrt(std::max(0.0, s * (2.0 - s)));
                                sum +=
                                    f(sinTheta * e + cosTheta * cap.spec.axis) * dsdT * weight[i] * (t1 - t0);
                            }
                        }
                        integrals[static_cast<std::size_t>(cap.firstCell + row * columns + column)] +=
                            sum * dPhi;
                    }
                }
        }
    }
    return integrals;
}

void LobeDomain::sAt(const Cap& cap, double T, double& s, double& dsdT) const
{
    const double t = T * cap.tExtent;
    if (cap.spec.scale > 0.0)
    {
        s = cap.spec.scale * std::expm1(t);
        dsdT = cap.tExtent * cap.spec.scale * std::exp(t);
    }
    else
    {
        s = t;
        dsdT = cap.tExtent;
    }
}

glm::dvec3 LobeDomain::pointAt(const Cap& cap, const glm::dvec3& e, double T) const
{
    double s, dsdT;
    sAt(cap, T, s, dsdT);
    const double cosTheta = 1.0 - s;
    const double sinTheta = std::sqrt(std::max(0.0, s * (2.0 - s)));
    return sinTheta * e + cosTheta * cap.spec.axis;
}

std::vector<double> LobeDomain::expectedCounts(const std::function<double(const glm::dvec3&)>& pdf,
                                               long samples, int subdivisions) const
{
    return countsWithOtherCell(cellIntegrals(pdf, subdivisions), samples);
}

double LobeDomain::integrate(const std::function<double(const glm::dvec3&)>& f, int subdivisions) const
{
    return sum(cellIntegrals(f, subdivisions));
}

WarpedDomain::WarpedDomain(std::vector<WarpedPart> parts) : m_parts(std::move(parts))
{
    for (const WarpedPart& part : m_parts)
    {
        m_firstCell.push_back(m_cellCount);
        m_cellCount += part.cells.cellCount() - 1;
    }
}

int WarpedDomain::cell(const glm::dvec3& direction) const
{
    for (std::size_t p = 0; p < m_parts.size(); ++p)
    {
        glm::dvec3 x;
        if (!m_parts[p].toCells(direction, x))
            continue;
        const int c = m_parts[p].cells.cell(x);
        return c == m_parts[p].cells.otherCell() ? otherCell() : m_firstCell[p] + c;
    }
    return otherCell();
}

std::vector<double> WarpedDomain::cellIntegrals(const std::function<double(const glm::dvec3&)>& f,
                                                int subdivisions) const
{
    std::vector<double> integrals;
    for (const WarpedPart& part : m_parts)
    {
        const auto partIntegrals = part.cells.cellIntegrals(
            [&](const glm::dvec3& x) {
                glm::dvec3 d;
                double jacobian;
                return part.fromCells(x, d, jacobian) ? f(d) * jacobian : 0.0;
            },
            subdivisions);
        integrals.insert(integrals.end(), partIntegrals.begin(), partIntegrals.end());
    }
    return integrals;
}

std::vector<double> WarpedDomain::expectedCounts(const std::function<double(const glm::dvec3&)>& pdf,
                                                 long samples, int subdivisions) const
{
    return countsWithOtherCell(cellIntegrals(pdf, subdivisions), samples);
}

double WarpedDomain::integrate(const std::function<double(const glm::dvec3&)>& f, int subdivisions) const
{
    return sum(cellIntegrals(f, subdivisions));
}
} // namespace rt::test
