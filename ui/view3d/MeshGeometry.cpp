#include "MeshGeometry.h"

#include <cmath>
#include <cstring>

namespace sortie::ui {

namespace {
// Qt Quick 3D shades in linear light and writes sRGB: a colour given as the operator sees it
// (sRGB, as the 2D map's) is made linear here, so the route is drawn in the map's own colour.
float linear(float srgb)
{
    return srgb <= 0.04045f ? srgb / 12.92f : std::pow((srgb + 0.055f) / 1.055f, 2.4f);
}
} // namespace

MeshGeometry::MeshGeometry(QQuick3DObject *parent) : QQuick3DGeometry(parent)
{
    // described from the start: Qt Quick 3D divides by the stride of a geometry with no data yet
    setMesh({});
}

void MeshGeometry::setMesh(const scene3d::Mesh &mesh)
{
    constexpr int stride = 10 * int(sizeof(float));
    QByteArray vertices(qsizetype(mesh.positions.size()) * stride, Qt::Uninitialized);
    auto *out = reinterpret_cast<float *>(vertices.data());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const QVector3D &p = mesh.positions[i], &n = mesh.normals[i];
        const QVector4D &c = mesh.colours[i];
        *out++ = p.x(); *out++ = p.y(); *out++ = p.z();
        *out++ = n.x(); *out++ = n.y(); *out++ = n.z();
        *out++ = linear(c.x()); *out++ = linear(c.y()); *out++ = linear(c.z()); *out++ = c.w();
    }
    QByteArray indices(qsizetype(mesh.indices.size() * sizeof(std::uint32_t)), Qt::Uninitialized);
    if (!mesh.indices.empty())
        std::memcpy(indices.data(), mesh.indices.data(), size_t(indices.size()));
    clear();
    setStride(stride);
    setPrimitiveType(QQuick3DGeometry::PrimitiveType::Triangles);
    addAttribute(QQuick3DGeometry::Attribute::PositionSemantic, 0, QQuick3DGeometry::Attribute::F32Type);
    addAttribute(QQuick3DGeometry::Attribute::NormalSemantic, 12, QQuick3DGeometry::Attribute::F32Type);
    addAttribute(QQuick3DGeometry::Attribute::ColorSemantic, 24, QQuick3DGeometry::Attribute::F32Type);
    addAttribute(QQuick3DGeometry::Attribute::IndexSemantic, 0, QQuick3DGeometry::Attribute::U32Type);
    setVertexData(vertices);
    setIndexData(indices);
    setBounds(mesh.minimum(), mesh.maximum());
    m_triangles = int(mesh.triangleCount());
    update();
    emit meshChanged();
}

} // namespace sortie::ui
