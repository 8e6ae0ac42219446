#pragma once

#include "MapLayer.h"

#include <QGeoCoordinate>
#include <QPointer>

namespace sortie::coverage {
class PhotoSurvey;
}

namespace sortie::ui {

// The replayed flight's photos on the map (issue 34): where each placed photo was taken (a dot),
// and the holes of its coverage (the ground seen by too few images, outlined and shaded in the
// colour of what is far off, with its area). It draws what PhotoSurvey found: no rule of its own.
class PhotoLayer : public MapLayer
{
    Q_OBJECT
    Q_MOC_INCLUDE("PhotoSurvey.h")
    QML_ELEMENT
    Q_PROPERTY(sortie::coverage::PhotoSurvey *survey READ survey WRITE setSurvey NOTIFY surveyChanged)
    Q_PROPERTY(int photoCount READ photoCount NOTIFY marksChanged)
    Q_PROPERTY(int holeCount READ holeCount NOTIFY marksChanged)

public:
    explicit PhotoLayer(QQuickItem *parent = nullptr);

    coverage::PhotoSurvey *survey() const { return m_survey; }
    void setSurvey(coverage::PhotoSurvey *survey);
    int photoCount() const { return int(m_photos.size()); }
    int holeCount() const { return int(m_holes.size()); }
    // Where a photo's dot is drawn, in this item's coordinates (for tests); NaN when none.
    Q_INVOKABLE QPointF photoPosition(int index) const;
    // The middle of a hole as drawn (its centroid), in this item's coordinates; NaN when none.
    Q_INVOKABLE QPointF holePosition(int index) const;

    void paint(QPainter *painter) override;

signals:
    void surveyChanged();
    void marksChanged();

protected:
    void onLanguageChanged() override { readMarks(); }

private:
    struct HoleMark
    {
        std::vector<QGeoCoordinate> ring;
        QGeoCoordinate centre;
        QString label;
    };
    void readMarks();

    QPointer<coverage::PhotoSurvey> m_survey;
    std::vector<QGeoCoordinate> m_photos;
    std::vector<HoleMark> m_holes;
};

} // namespace sortie::ui
