#pragma once

#include "Theme.h"

#include <QColor>
#include <QPointer>
#include <QQuickPaintedItem>
#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// A heading compass card: the card turns so that the vehicle's heading is at the top under the
// lubber line; marks on the rim show the bearing to home (H, square) and to the next waypoint
// (triangle). Drawn with QPainter, so it renders offscreen. NaN hides what is unknown.
class HeadingCompass : public QQuickPaintedItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(double heading READ heading WRITE setHeading NOTIFY changed)             // deg from north, clockwise (bearings too)
    Q_PROPERTY(double bearingToHome READ bearingToHome WRITE setBearingToHome NOTIFY changed)
    Q_PROPERTY(double bearingToNext READ bearingToNext WRITE setBearingToNext NOTIFY changed)
    // The card's words, home's and the next waypoint's marks come from the theme (light without one).
    Q_PROPERTY(sortie::ui::Theme *theme READ theme WRITE setTheme NOTIFY changed)

public:
    explicit HeadingCompass(QQuickItem *parent = nullptr);

    double heading() const { return m_heading; }
    void setHeading(double degrees);
    double bearingToHome() const { return m_home; }
    void setBearingToHome(double degrees);
    double bearingToNext() const { return m_next; }
    void setBearingToNext(double degrees);
    Theme *theme() const { return m_theme; }
    void setTheme(Theme *theme);

    // Where a bearing's mark sits on the rim, in item pixels (a null point when not shown).
    Q_INVOKABLE QPointF markPosition(double bearing) const;

    void paint(QPainter *painter) override;

signals:
    void changed();

private:
    void set(double &field, double value);
    double m_heading = qQNaN();
    double m_home = qQNaN();
    double m_next = qQNaN();
    QPointer<Theme> m_theme;
};

} // namespace sortie::ui
