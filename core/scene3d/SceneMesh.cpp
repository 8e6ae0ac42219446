#include "SceneMesh.h"

#include <algorithm>

namespace sortie::scene3d {

void Mesh::append(const Mesh &other)
{
    const std::uint32_t base = vertexCount();
    positions.insert(positions.end(), other.positions.begin(), other.positions.end());
    normals.insert(normals.end(), other.normals.begin(), other.normals.end());
    colours.insert(colours.end(), other.colours.begin(), other.colours.end());
    indices.reserve(indices.size() + other.indices.size());
    for (std::uint32_t i : other.indices)
        indices.push_back(base + i);
}

QVector3D Mesh::minimum() const
{
    if (positions.empty())
        return {};
    QVector3D m = positions.front();
    for (const QVector3D &p : positions)
        m = QVector3D(std::min(m.x(), p.x()), std::min(m.y(), p.y()), std::min(m.z(), p.z()));
    return m;
}

QVector3D Mesh::maximum() const
{
    if (positions.empty())
        return {};
    QVector3D m = positions.front();
    for (const QVector3D &p : positions)
        m = QVector3D(std::max(m.x(), p.x()), std::max(m.y(), p.y()), std::max(m.z(), p.z()));
    return m;
}

QVector4D rgba(const QColor &colour, float alpha)
{
    return QVector4D(float(colour.redF()), float(colour.greenF()), float(colour.blueF()), alpha < 0 ? float(colour.alphaF()) : alpha);
}

} // namespace sortie::scene3d
