#include "OutsideDatabase.h"

#include <QCoreApplication>
#include <QHash>
#include <QMutex>
#include <QSqlDriver>
#include <QSqlError>
#include <QUrl>
#include <QVariant>

#include <sqlite3.h>

namespace sortie::sqlite {

namespace {

constexpr int kStepsPerCall = 1000;  // how often SQLite calls the progress handler

// The bounds of one connection, freed by SQLite when the connection closes (as a function's
// destructor), and found by its handle for statementStopped().
struct Bounds
{
    sqlite3 *handle = nullptr;
    OutsideLimits limits;
    qint64 rows = 0;
    qint64 steps = 0;
    QString stopped;
};

QMutex g_boundsMutex;
QHash<sqlite3 *, Bounds *> g_bounds;

void forget(void *context)
{
    auto *b = static_cast<Bounds *>(context);
    {
        QMutexLocker lock(&g_boundsMutex);
        g_bounds.remove(b->handle);
    }
    delete b;
}

void noFunction(sqlite3_context *context, int, sqlite3_value **)
{
    sqlite3_result_null(context);
}

int onProgress(void *context)
{
    auto *b = static_cast<Bounds *>(context);
    b->steps += kStepsPerCall;
    if (b->steps <= b->limits.maxSteps)
        return 0;
    if (b->stopped.isEmpty())
        b->stopped = QCoreApplication::translate("OutsideDatabase", "more than %1 steps").arg(b->limits.maxSteps);
    return 1;  // the statement ends with SQLITE_INTERRUPT
}

// A statement starting resets the counts; each row it returns is counted.
int onTrace(unsigned kind, void *context, void *statement, void *)
{
    auto *b = static_cast<Bounds *>(context);
    if (kind == SQLITE_TRACE_STMT) {
        b->rows = b->steps = 0;
        b->stopped.clear();
    } else if (kind == SQLITE_TRACE_ROW && ++b->rows > b->limits.maxRows) {
        if (b->stopped.isEmpty())
            b->stopped = QCoreApplication::translate("OutsideDatabase", "more than %1 rows").arg(b->limits.maxRows);
        sqlite3_interrupt(sqlite3_db_handle(static_cast<sqlite3_stmt *>(statement)));  // its next step fails
    }
    return 0;
}

sqlite3 *handleOf(const QSqlDatabase &db)
{
    if (!db.isOpen() || !db.driver())
        return nullptr;
    const QVariant v = db.driver()->handle();
    if (!v.isValid() || qstrcmp(v.typeName(), "sqlite3*") != 0)
        return nullptr;
    return *static_cast<sqlite3 *const *>(v.constData());
}

bool harden(sqlite3 *h, const OutsideLimits &limits)
{
    const std::pair<int, int> settings[] = {
        {SQLITE_DBCONFIG_DEFENSIVE, 1},
        {SQLITE_DBCONFIG_WRITABLE_SCHEMA, 0},
        {SQLITE_DBCONFIG_TRUSTED_SCHEMA, 0},
        {SQLITE_DBCONFIG_ENABLE_TRIGGER, 0},
        {SQLITE_DBCONFIG_ENABLE_VIEW, limits.views ? 1 : 0},
        {SQLITE_DBCONFIG_ENABLE_LOAD_EXTENSION, 0},
    };
    for (const auto &[option, value] : settings) {
        int now = -1;
        if (sqlite3_db_config(h, option, value, &now) != SQLITE_OK || now != value)
            return false;
    }
    sqlite3_limit(h, SQLITE_LIMIT_LENGTH, limits.maxValueBytes);
    sqlite3_limit(h, SQLITE_LIMIT_ATTACHED, 0);
    auto *bounds = new Bounds{h, limits, 0, 0, {}};
    if (sqlite3_create_function_v2(h, "sortie_outside_bounds", 0, SQLITE_UTF8 | SQLITE_DIRECTONLY, bounds, noFunction, nullptr,
                                   nullptr, forget)
        != SQLITE_OK) {
        delete bounds;
        return false;
    }
    {
        QMutexLocker lock(&g_boundsMutex);
        g_bounds.insert(h, bounds);
    }
    sqlite3_progress_handler(h, kStepsPerCall, onProgress, bounds);
    sqlite3_trace_v2(h, SQLITE_TRACE_STMT | SQLITE_TRACE_ROW, onTrace, bounds);
    return true;
}

} // namespace

QSqlDatabase openOutside(const QString &path, const QString &connection, Access access, const OutsideLimits &limits, QString *error)
{
    QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), connection);
    db.setDatabaseName(path);
    if (access == Access::ReadOnly)
        db.setConnectOptions(QStringLiteral("QSQLITE_OPEN_READONLY"));
    if (!db.open()) {
        if (error)
            *error = db.lastError().text();
        return db;
    }
    sqlite3 *h = handleOf(db);
    if (!h || !harden(h, limits)) {
        db.close();
        if (error)
            *error = QCoreApplication::translate("OutsideDatabase", "SQLite refused the settings a file from outside is read with");
    }
    return db;
}

QString statementStopped(const QSqlDatabase &db)
{
    sqlite3 *h = handleOf(db);
    QMutexLocker lock(&g_boundsMutex);
    const Bounds *b = h ? g_bounds.value(h) : nullptr;
    return b ? b->stopped : QString();
}

} // namespace sortie::sqlite
