#include "HeadingCompass.h"

#include <QPainter>
#include <QPainterPath>

#include <cmath>
#include <numbers>

namespace sortie::ui {

HeadingCompass::HeadingCompass(QQuickItem *parent)
    : QQuickPaintedItem(parent)
{
    setAntialiasing(true);
    setImplicitSize(150, 150);
}

void HeadingCompass::set(double &field, double value)
{
    if (field == value || (std::isnan(field) && std::isnan(value)))
        return;
    field = value;
    update();
    emit changed();
}

void HeadingCompass::setHeading(double degrees) { set(m_heading, degrees); }
void HeadingCompass::setBearingToHome(double degrees) { set(m_home, degrees); }
void HeadingCompass::setBearingToNext(double degrees) { set(m_next, degrees); }

void HeadingCompass::setTheme(Theme *theme)
{
    if (theme == m_theme)
        return;
    if (m_theme)
        disconnect(m_theme, nullptr, this, nullptr);
    m_theme = theme;
    if (m_theme)
        connect(m_theme, &Theme::coloursChanged, this, [this] { update(); });
    update();
    emit changed();
}

QPointF HeadingCompass::markPosition(double bearing) const
{
    if (!std::isfinite(bearing))
        return {};
    const double r = std::min(width(), height()) / 2 - 2;
    // The card turns so that the heading is up; without a heading north is up.
    const double up = std::isfinite(m_heading) ? m_heading : 0.0;
    const double angle = (bearing - up) * std::numbers::pi / 180.0; // sin and cos take radians
    return QPointF(width() / 2 + std::sin(angle) * (r - 9), height() / 2 - std::cos(angle) * (r - 9));
}

void HeadingCompass::paint(QPainter *painter)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const double side = std::min(width(), height());
    if (side < 20)
        return;
    const double r = side / 2 - 2;
    const QPointF centre(width() / 2, height() / 2);
    const double up = std::isfinite(m_heading) ? m_heading : 0.0;

    const ThemeColours &colours = coloursOf(m_theme);
    const QColor text = colours.windowText;
    QColor face = text;
    face.setAlpha(18);
    painter->setPen(QPen(text, 1.5));
    painter->setBrush(face);
    painter->drawEllipse(centre, r, r);

    // The card: ticks every 10°, letters at the cardinal points, numbers every 30°.
    QFont font = painter->font();
    font.setPixelSize(std::max(8, int(side / 14)));
    font.setBold(true);
    painter->setFont(font);
    painter->save();
    painter->translate(centre);
    painter->rotate(-up);
    static const char *const kCardinal[] = {"N", "E", "S", "W"};
    for (int deg = 0; deg < 360; deg += 10) {
        painter->save();
        painter->rotate(deg);
        const bool major = deg % 30 == 0;
        painter->setPen(QPen(deg == 0 ? colours.map.noReturn : text, major ? 2 : 1));
        painter->drawLine(QPointF(0, -r + 1), QPointF(0, -r + (major ? 10 : 6)));
        if (major) {
            const QString label = deg % 90 == 0 ? QString::fromLatin1(kCardinal[deg / 90]) : QString::number(deg / 10);
            painter->drawText(QRectF(-14, -r + 11, 28, 16), Qt::AlignCenter, label);
        }
        painter->restore();
    }
    painter->restore();

    // Home (a square with H) and the next waypoint (a triangle), on the rim at their bearings.
    auto markAt = [&](double bearing) { return markPosition(bearing) - QPointF(width() / 2, height() / 2) + centre; };
    if (std::isfinite(m_next)) {
        const QPointF at = markAt(m_next);
        const double angle = m_next - up;
        painter->save();
        painter->translate(at);
        painter->rotate(angle);
        QPainterPath triangle;
        triangle.moveTo(0, -7);
        triangle.lineTo(6, 5);
        triangle.lineTo(-6, 5);
        triangle.closeSubpath();
        painter->setPen(QPen(colours.map.outline, 1));
        painter->setBrush(colours.map.unplanned);
        painter->drawPath(triangle);
        painter->restore();
    }
    if (std::isfinite(m_home)) {
        const QPointF at = markAt(m_home);
        const QRectF box(at - QPointF(7, 7), QSizeF(14, 14));
        painter->setPen(QPen(colours.map.outline, 1));
        painter->setBrush(colours.map.planned);
        painter->drawRect(box);
        QFont small = font;
        small.setPixelSize(10);
        painter->setFont(small);
        painter->setPen(colours.map.markText);
        painter->drawText(box, Qt::AlignCenter, QStringLiteral("H"));
        painter->setFont(font);
    }

    // The lubber line and the vehicle in the middle, pointing up; the heading in figures.
    painter->setPen(QPen(colours.map.attention, 3, Qt::SolidLine, Qt::RoundCap));
    painter->drawLine(centre + QPointF(0, -r - 1), centre + QPointF(0, -r + 12));
    QPainterPath arrow;
    arrow.moveTo(0, -r * 0.32);
    arrow.lineTo(r * 0.16, r * 0.2);
    arrow.lineTo(0, r * 0.1);
    arrow.lineTo(-r * 0.16, r * 0.2);
    arrow.closeSubpath();
    painter->setPen(QPen(text, 1));
    painter->setBrush(colours.map.attention);
    painter->drawPath(arrow.translated(centre));
    painter->setPen(text);
    painter->setFont(font);
    const QString figures = std::isfinite(m_heading)
                                ? QStringLiteral("%1°").arg((int(std::lround(m_heading)) % 360 + 360) % 360, 3, 10, QLatin1Char('0'))
                                : QStringLiteral("—");
    painter->drawText(QRectF(centre.x() - 30, centre.y() + r * 0.26, 60, 18), Qt::AlignCenter, figures);
}

} // namespace sortie::ui
