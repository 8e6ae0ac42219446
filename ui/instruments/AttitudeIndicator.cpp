#include "AttitudeIndicator.h"

#include "LanguageChange.h"

#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace sortie::ui {

namespace {
bool same(double a, double b)
{
    return a == b || (std::isnan(a) && std::isnan(b));
}
} // namespace

AttitudeIndicator::AttitudeIndicator(QQuickItem *parent)
    : QQuickPaintedItem(parent)
{
    setAntialiasing(true);
    setImplicitSize(150, 150);
    i18n::onLanguageChange(this, [this] { update(); }); // "no attitude" is worded as painted
}

void AttitudeIndicator::setRoll(double degrees)
{
    if (same(degrees, m_roll))
        return;
    m_roll = degrees;
    update();
    emit attitudeChanged();
}

void AttitudeIndicator::setPitch(double degrees)
{
    if (same(degrees, m_pitch))
        return;
    m_pitch = degrees;
    update();
    emit attitudeChanged();
}

void AttitudeIndicator::setTheme(Theme *theme)
{
    if (theme == m_theme)
        return;
    if (m_theme)
        disconnect(m_theme, nullptr, this, nullptr);
    m_theme = theme;
    if (m_theme)
        connect(m_theme, &Theme::coloursChanged, this, [this] { update(); });
    update();
    emit themeChanged();
}

void AttitudeIndicator::paint(QPainter *painter)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const ThemeColours &colours = coloursOf(m_theme);
    const QColor text = colours.windowText;
    const QColor sky = colours.map.sky, ground = colours.map.ground, dial = colours.map.dial, symbol = colours.map.attention;
    QColor blank = colours.mid;
    blank.setAlpha(90);
    const double side = std::min(width(), height());
    if (side < 20)
        return;
    const double r = side / 2 - 2;
    const QPointF centre(width() / 2, height() / 2);
    QPainterPath face;
    face.addEllipse(centre, r, r);

    if (!hasAttitude()) {
        painter->setPen(QPen(text, 1.5));
        painter->setBrush(blank);
        painter->drawPath(face);
        QFont font = painter->font();
        font.setPixelSize(std::max(9, int(side / 12)));
        painter->setFont(font);
        painter->drawText(QRectF(centre.x() - r, centre.y() - r, 2 * r, 2 * r), Qt::AlignCenter, tr("no attitude"));
        return;
    }

    // The horizon: pixels per degree of pitch so that ±30° spans the face.
    const double pixelsPerDegree = r / 30.0;
    const double pitchDeg = std::clamp(m_pitch, -90.0, 90.0);
    painter->save();
    painter->setClipPath(face);
    painter->translate(centre);
    painter->rotate(-m_roll);
    painter->translate(0, pitchDeg * pixelsPerDegree);
    const double big = side * 3;
    painter->fillRect(QRectF(-big, -big, 2 * big, big), sky);
    painter->fillRect(QRectF(-big, 0, 2 * big, big), ground);
    painter->setPen(QPen(dial, 2));
    painter->drawLine(QPointF(-big, 0), QPointF(big, 0));
    // The pitch ladder, every 10° (short marks at 5°).
    QFont font = painter->font();
    font.setPixelSize(std::max(8, int(side / 16)));
    painter->setFont(font);
    painter->setPen(QPen(dial, 1.2));
    for (int deg = -60; deg <= 60; deg += 5) {
        if (deg == 0)
            continue;
        const double y = -deg * pixelsPerDegree;
        const double half = deg % 10 == 0 ? r * 0.28 : r * 0.12;
        painter->drawLine(QPointF(-half, y), QPointF(half, y));
        if (deg % 10 == 0) {
            const QString label = QString::number(std::abs(deg));
            painter->drawText(QRectF(half + 2, y - 8, 24, 16), Qt::AlignLeft | Qt::AlignVCenter, label);
            painter->drawText(QRectF(-half - 26, y - 8, 24, 16), Qt::AlignRight | Qt::AlignVCenter, label);
        }
    }
    painter->restore();

    // The roll scale (fixed) and its pointer (turns with the roll).
    painter->save();
    painter->translate(centre);
    painter->setPen(QPen(dial, 1.5));
    for (int deg : {-60, -45, -30, -20, -10, 0, 10, 20, 30, 45, 60}) {
        painter->save();
        painter->rotate(deg);
        const double inner = deg % 30 == 0 ? r - 12 : r - 7;
        painter->drawLine(QPointF(0, -r + 1), QPointF(0, -inner));
        painter->restore();
    }
    painter->rotate(-m_roll);
    QPainterPath pointer;
    pointer.moveTo(0, -r + 13);
    pointer.lineTo(-6, -r + 23);
    pointer.lineTo(6, -r + 23);
    pointer.closeSubpath();
    painter->setPen(Qt::NoPen);
    painter->setBrush(symbol);
    painter->drawPath(pointer);
    painter->restore();

    // The aircraft: fixed wings and a centre dot.
    painter->setPen(QPen(symbol, 4, Qt::SolidLine, Qt::RoundCap));
    painter->drawLine(centre + QPointF(-r * 0.55, 0), centre + QPointF(-r * 0.18, 0));
    painter->drawLine(centre + QPointF(-r * 0.18, 0), centre + QPointF(-r * 0.10, r * 0.08));
    painter->drawLine(centre + QPointF(r * 0.55, 0), centre + QPointF(r * 0.18, 0));
    painter->drawLine(centre + QPointF(r * 0.18, 0), centre + QPointF(r * 0.10, r * 0.08));
    painter->setBrush(symbol);
    painter->drawEllipse(centre, 2.5, 2.5);

    painter->setBrush(Qt::NoBrush);
    painter->setPen(QPen(text, 1.5));
    painter->drawPath(face);
}

} // namespace sortie::ui
