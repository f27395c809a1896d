#include "Geometry/Packets.h"

namespace rt::cpu
{
void setLane(SpherePacket& p, int lane, const SphereRec& s, std::uint32_t prim)
{
    p.cx[lane] = s.center0.x;
    p.cy[lane] = s.center0.y;
    p.cz[lane] = s.center0.z;
    p.vx[lane] = s.velocity.x;
    p.vy[lane] = s.velocity.y;
    p.vz[lane] = s.velocity.z;
    p.radius2[lane] = s.radius * s.radius;
    p.radius[lane] = s.radius;
    p.prim[lane] = prim;
}

void setLane(QuadPacket& p, int lane, const QuadRec& q, std::uint32_t prim)
{
    p.qx[lane] = q.q.x;
    p.qy[lane] = q.q.y;
    p.qz[lane] = q.q.z;
    p.nx[lane] = q.normal.x;
    p.ny[lane] = q.normal.y;
    p.nz[lane] = q.normal.z;
    p.d[lane] = q.d;
    p.uax[lane] = q.ua.x;
    p.uay[lane] = q.ua.y;
    p.uaz[lane] = q.ua.z;
    p.vbx[lane] = q.vb.x;
    p.vby[lane] = q.vb.y;
    p.vbz[lane] = q.vb.z;
    p.prim[lane] = prim;
}

void setLane(TrianglePacket& p, int lane, const TriangleRec& t, std::uint32_t prim)
{
    const vec3* v[3] = {&t.p0, &t.p1, &t.p2};
    for (int i = 0; i < 3; ++i)
        for (int axis = 0; axis < 3; ++axis)
            p.p[i][axis][lane] = (*v[i])[axis];
    p.prim[lane] = prim;
}
} // namespace rt::cpu
