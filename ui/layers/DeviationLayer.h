#pragma once

#include "MapLayer.h"
#include "ModelCoordinates.h"

namespace sortie::ui {

// A flown track coloured by how far it strayed from the plan: consecutive points of any list
// model with latitude, longitude and level roles (0 fine, 1 warning, 2 bad; see
// flightlog::deviationLevel), drawn as segments in green, amber and red.
class DeviationLayer : public MapLayer
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QAbstractItemModel *model READ model WRITE setModel NOTIFY modelChanged)
    Q_PROPERTY(int count READ count NOTIFY modelChanged)

public:
    explicit DeviationLayer(QQuickItem *parent = nullptr);

    QAbstractItemModel *model() const { return m_points.model(); }
    void setModel(QAbstractItemModel *model);
    int count() const { return m_points.count(); }
    // The colour a level is drawn in.
    // On time, a little off, far off: the map palette's planned, unplanned and no-return colours.
    static QColor levelColour(const MapPalette &colours, int level);

    void paint(QPainter *painter) override;

signals:
    void modelChanged();

private:
    void readLevels();

    ModelCoordinates m_points;
    std::vector<int> m_levels;
};

} // namespace sortie::ui
