#include "LanguageChange.h"

#include <QAbstractItemModel>
#include <QCoreApplication>
#include <QEvent>

namespace sortie::i18n {

namespace {
// A child of the owner (so it goes with it) that watches the application's events.
class Watcher : public QObject
{
public:
    Watcher(QObject *owner, std::function<void()> refresh)
        : QObject(owner)
        , m_refresh(std::move(refresh))
    {
        if (QCoreApplication *app = QCoreApplication::instance())
            app->installEventFilter(this);
    }

    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (event->type() == QEvent::LanguageChange && watched == QCoreApplication::instance())
            m_refresh();
        return false;
    }

private:
    std::function<void()> m_refresh;
};
} // namespace

void onLanguageChange(QObject *owner, std::function<void()> refresh)
{
    new Watcher(owner, std::move(refresh));
}

void refreshOnLanguageChange(QAbstractItemModel *model)
{
    onLanguageChange(model, [model] {
        const int rows = model->rowCount(), columns = model->columnCount();
        if (rows > 0 && columns > 0)
            emit model->dataChanged(model->index(0, 0), model->index(rows - 1, columns - 1));
        if (columns > 0)
            emit model->headerDataChanged(Qt::Horizontal, 0, columns - 1);
    });
}

} // namespace sortie::i18n
