#pragma once

#include <QByteArray>
#include <QObject>
#include <QPointF>
#include <QPointer>

#include <vector>

#include <QAbstractItemModel>

namespace sortie::ui {

// Follows a list model's latitude/longitude roles and keeps every row's position projected
// (normalised Web Mercator), updated row by row on dataChanged and in full on structural
// changes, so layers never read the model while drawing. Rows without a valid position hold NaN.
class ModelCoordinates : public QObject
{
    Q_OBJECT

public:
    explicit ModelCoordinates(QObject *parent = nullptr);

    QAbstractItemModel *model() const { return m_model; }
    void setModel(QAbstractItemModel *model);
    QByteArray latitudeRole() const { return m_latitudeRole; }
    QByteArray longitudeRole() const { return m_longitudeRole; }
    void setRoleNames(const QByteArray &latitude, const QByteArray &longitude);

    const std::vector<QPointF> &points() const { return m_points; }
    int count() const { return int(m_points.size()); }
    bool isValid(int row) const;
    // The role id of a name in the current model, or -1.
    int roleId(const QByteArray &name) const;

signals:
    // Positions of rows first..last changed; after a structural change first = 0, last = count - 1.
    void changed(int first, int last);

private:
    void reload();
    void reloadRows(int first, int last);
    void resolveRoles();

    QPointer<QAbstractItemModel> m_model;
    QByteArray m_latitudeRole = "latitude";
    QByteArray m_longitudeRole = "longitude";
    int m_latitudeId = -1;
    int m_longitudeId = -1;
    std::vector<QPointF> m_points;
};

// Moves b by whole worlds so that it is the copy nearest a (for lines across the antimeridian).
inline QPointF nearestCopy(QPointF a, QPointF b)
{
    double dx = b.x() - a.x();
    dx -= double(qRound64(dx));
    return {a.x() + dx, b.y()};
}

} // namespace sortie::ui
