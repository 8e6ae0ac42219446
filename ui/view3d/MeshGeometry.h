#pragma once

#include "SceneMesh.h"

#include <QQuick3DGeometry>
#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// A core mesh (scene3d::Mesh) as Qt Quick 3D geometry: position, normal and RGBA colour per vertex
// (40 bytes), 32-bit indices, triangles. Setting a mesh uploads it once; nothing else redraws it.
class MeshGeometry : public QQuick3DGeometry
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("made by FlightScene")
    Q_PROPERTY(int triangleCount READ triangleCount NOTIFY meshChanged)

public:
    explicit MeshGeometry(QQuick3DObject *parent = nullptr);
    void setMesh(const scene3d::Mesh &mesh);
    int triangleCount() const { return m_triangles; }

signals:
    void meshChanged();

private:
    int m_triangles = 0;
};

} // namespace sortie::ui
