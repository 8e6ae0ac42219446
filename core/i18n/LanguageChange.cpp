#include "LanguageChange.h"

#include <QAbstractItemModel>
#include <QCoreApplication>
#include <QEvent>

namespace sortie::i18n {

namespace {
// One filter on the application for every listener (an application's event filter sees each event
// of the program, so one, not one per listener), made on first use as the application's child and
// found there again: it goes with the application, and a new application gets its own.
class Hub : public QObject
{
    Q_OBJECT
public:
    static Hub *of(QCoreApplication *app)
    {
        static const QString kName = QStringLiteral("sortie-i18n-language-change");
        if (auto *hub = app->findChild<Hub *>(kName, Qt::FindDirectChildrenOnly))
            return hub;
        auto *hub = new Hub(app);
        hub->setObjectName(kName);
        app->installEventFilter(hub);
        return hub;
    }

    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (event->type() == QEvent::LanguageChange && watched == parent())
            emit changed();
        return false;
    }

signals:
    void changed();

private:
    using QObject::QObject;
};
} // namespace

void onLanguageChange(QObject *owner, std::function<void()> refresh)
{
    if (QCoreApplication *app = QCoreApplication::instance())
        QObject::connect(Hub::of(app), &Hub::changed, owner, std::move(refresh)); // gone with the owner
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

#include "LanguageChange.moc"
