#include "VisualCheck.h"

#include "MapView.h"

#include <QFontDatabase>
#include <QFontMetricsF>
#include <QHash>
#include <QQuickWindow>

#include <cmath>

namespace sortie::test {

namespace {

int g_inspected = 0;

struct ShownText
{
    QQuickItem *item;
    QRectF box;  // the painted text, in scene coordinates
    QString text;
};

QString describe(const QQuickItem *item, const QString &text)
{
    QString path;
    for (const QQuickItem *i = item; i; i = i->parentItem())
        if (!i->objectName().isEmpty()) {
            path = i->objectName();
            break;
        }
    return QStringLiteral("“%1”%2").arg(text.left(60), path.isEmpty() ? QString() : QStringLiteral(" (in %1)").arg(path));
}

bool shown(const QQuickItem *item)
{
    if (!item->isVisible() || item->width() <= 0 || item->height() <= 0)
        return false;
    double opacity = 1;
    for (const QQuickItem *i = item; i; i = i->parentItem())
        opacity *= i->opacity();
    return opacity > 0.01;
}

QRectF sceneRect(const QQuickItem *item)
{
    return item->mapRectToScene(QRectF(0, 0, item->width(), item->height()));
}

// Inside every clipping ancestor, i.e. not scrolled away in a list or a flickable.
bool inView(const QQuickItem *item)
{
    const QRectF rect = sceneRect(item).adjusted(1, 1, -1, -1);
    for (const QQuickItem *i = item->parentItem(); i; i = i->parentItem())
        if (i->clip() && !sceneRect(i).contains(rect))
            return false;
    return true;
}

// Whether some installed font draws the character (Qt falls back to those).
bool anyFontHas(char32_t c)
{
    static QHash<char32_t, bool> known;
    const auto found = known.constFind(c);
    if (found != known.cend())
        return found.value();
    bool has = false;
    for (const QString &family : QFontDatabase::families()) {
        if (QFontMetricsF(QFont(family)).inFontUcs4(c)) {
            has = true;
            break;
        }
    }
    known.insert(c, has);
    return has;
}

QRectF paintedBox(const QQuickItem *item)
{
    const double w = std::min(item->width(), item->property("contentWidth").toDouble());
    const double h = std::min(item->height(), item->property("contentHeight").toDouble());
    double x = 0, y = 0;
    const int h_align = item->property("effectiveHorizontalAlignment").toInt();
    if (h_align & Qt::AlignRight)
        x = item->width() - w;
    else if (h_align & Qt::AlignHCenter)
        x = (item->width() - w) / 2;
    const int v_align = item->property("verticalAlignment").toInt();
    if (v_align & Qt::AlignBottom)
        y = item->height() - h;
    else if (v_align & Qt::AlignVCenter)
        y = (item->height() - h) / 2;
    return item->mapRectToScene(QRectF(x, y, w, h));
}

void collect(QQuickItem *item, std::vector<ShownText> &out)
{
    if (!shown(item))
        return;
    if (item->inherits("QQuickText")) {
        const QString text = item->property("text").toString();
        if (!text.trimmed().isEmpty() && inView(item))
            out.push_back({item, paintedBox(item), text});
    }
    for (QQuickItem *child : item->childItems())
        collect(child, out);
}

bool isAncestor(const QQuickItem *a, const QQuickItem *b)
{
    for (const QQuickItem *i = b->parentItem(); i; i = i->parentItem())
        if (i == a)
            return true;
    return false;
}

} // namespace

int lastInspectedTextCount()
{
    return g_inspected;
}

QStringList inspectTexts(QQuickItem *scope)
{
    QStringList problems;
    std::vector<ShownText> texts;
    collect(scope, texts);
    g_inspected = int(texts.size());
    const QRectF window = scope->window() ? QRectF(QPointF(0, 0), scope->window()->size()) : QRectF();
    for (const ShownText &t : texts) {
        QQuickItem *item = t.item;
        const bool elided = item->property("elide").toInt() != Qt::ElideNone;
        const bool wraps = item->property("wrapMode").toInt() != 0;
        const double width = item->width();
        const double needed = wraps ? item->property("contentWidth").toDouble() : item->implicitWidth();
        if (!elided && needed > width + 1.0)
            problems << QStringLiteral("clipped: %1 needs %2 px, has %3").arg(describe(item, t.text)).arg(needed, 0, 'f', 0).arg(width, 0, 'f', 0);
        const QRectF rect = sceneRect(item);
        if (!window.isEmpty() && !window.adjusted(-1, -1, 1, 1).contains(t.box))
            problems << QStringLiteral("out of the window: %1").arg(describe(item, t.text));
        for (const QQuickItem *i = item->parentItem(); i; i = i->parentItem()) {
            if (i->inherits("QQuickPopupItem")) {
                if (!sceneRect(i).adjusted(-1, -1, 1, 1).contains(t.box))
                    problems << QStringLiteral("past its frame: %1").arg(describe(item, t.text));
                break;
            }
        }
        Q_UNUSED(rect);
        const QFont font = item->property("font").value<QFont>();
        const QFontMetricsF metrics(font);
        for (char32_t c : t.text.toUcs4()) {
            if (QChar::isSpace(c) || c < 0x20 || c == 0x2029 || c == 0x2028)
                continue;
            if (!metrics.inFontUcs4(c) && !anyFontHas(c))
                problems << QStringLiteral("missing glyph U+%1 in %2").arg(uint(c), 4, 16, QLatin1Char('0')).arg(describe(item, t.text));
        }
    }
    for (size_t i = 0; i < texts.size(); ++i) {
        for (size_t j = i + 1; j < texts.size(); ++j) {
            const ShownText &a = texts[i], &b = texts[j];
            if (isAncestor(a.item, b.item) || isAncestor(b.item, a.item))
                continue;
            const QRectF overlap = a.box.intersected(b.box);
            if (overlap.width() > 1.0 && overlap.height() > 1.0)
                problems << QStringLiteral("overlapping: %1 and %2").arg(describe(a.item, a.text), describe(b.item, b.text));
        }
    }
    problems.removeDuplicates();
    return problems;
}

QStringList inspectMapControls(QQuickItem *pane, const QStringList &controls)
{
    QStringList problems;
    auto *map = pane->findChild<ui::MapView *>(QStringLiteral("mapView"));
    if (!map)
        return {QStringLiteral("no map in the pane")};
    const QList<QRectF> labels = map->graticuleLabelRects();
    const qreal top = map->labelBandTop(), left = map->labelBandLeft();
    const QRectF topBand(0, 0, map->width(), top), leftBand(0, 0, left, map->height());
    for (qsizetype i = 0; i < labels.size(); ++i)
        for (qsizetype j = i + 1; j < labels.size(); ++j)
            if (labels[i].intersects(labels[j]))
                problems << QStringLiteral("two graticule labels cross at (%1, %2)").arg(labels[j].x()).arg(labels[j].y());
    QList<std::pair<QString, QRectF>> placed;
    for (const QString &name : controls) {
        auto *item = pane->findChild<QQuickItem *>(name);
        if (!item || !item->isVisible() || item->width() <= 0 || item->height() <= 0)
            continue;
        const QRectF rect = item->mapRectToItem(map, QRectF(0, 0, item->width(), item->height()));
        for (const QRectF &label : labels)
            if (rect.intersects(label))
                problems << QStringLiteral("%1 covers a graticule label at (%2, %3)").arg(name).arg(label.x()).arg(label.y());
        if (rect.intersects(topBand) || rect.intersects(leftBand))
            problems << QStringLiteral("%1 reaches into the graticule's label band").arg(name);
        for (const auto &[other, otherRect] : placed)
            if (rect.intersects(otherRect))
                problems << QStringLiteral("%1 and %2 cover each other").arg(name, other);
        placed.append({name, rect});
    }
    return problems;
}

} // namespace sortie::test
