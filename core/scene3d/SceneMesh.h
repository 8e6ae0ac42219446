#pragma once

#include <QColor>
#include <QVector3D>
#include <QVector4D>

#include <cstdint>
#include <vector>

namespace sortie::scene3d {

// Triangles in the scene's frame (SceneFrame): a position, a normal and an RGBA colour per vertex,
// three indices per triangle. Walls, skirts, tubes and curtains are seen from both sides: the
// views draw them without back-face culling (one winding each, not two).
struct Mesh
{
    std::vector<QVector3D> positions;
    std::vector<QVector3D> normals;
    std::vector<QVector4D> colours;
    std::vector<std::uint32_t> indices;

    std::uint32_t vertexCount() const { return std::uint32_t(positions.size()); }
    std::size_t triangleCount() const { return indices.size() / 3; }
    bool empty() const { return indices.empty(); }
    std::uint32_t addVertex(const QVector3D &position, const QVector3D &normal, const QVector4D &colour)
    {
        positions.push_back(position);
        normals.push_back(normal);
        colours.push_back(colour);
        return std::uint32_t(positions.size() - 1);
    }
    void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c)
    {
        indices.push_back(a);
        indices.push_back(b);
        indices.push_back(c);
    }
    // Another mesh's triangles appended (its indices shifted).
    void append(const Mesh &other);
    // The box around every vertex (both corners zero when empty).
    QVector3D minimum() const;
    QVector3D maximum() const;
};

QVector4D rgba(const QColor &colour, float alpha = -1.0f);  // alpha < 0: the colour's own

} // namespace sortie::scene3d
