#include "AutosaveDirectory.h"

#include "PrivateFiles.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>
#include <QCoreApplication>

namespace sortie::client {

AutosaveDirectory::AutosaveDirectory(QString path)
    : m_path(std::move(path))
{
}

QString AutosaveDirectory::filePath(int slot) const
{
    return QDir(m_path).filePath(QStringLiteral("autosave-%1.json").arg(slot));
}

QString AutosaveDirectory::lockPath(int slot) const
{
    return QDir(m_path).filePath(QStringLiteral("autosave-%1.lock").arg(slot));
}

QString AutosaveDirectory::discardedPath() const
{
    return QDir(m_path).filePath(QStringLiteral("autosave-discarded.json"));
}

QString AutosaveDirectory::corruptPath(int slot) const
{
    const QString stamp = QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss-zzz"));
    QString path = QDir(m_path).filePath(QStringLiteral("autosave-%1.unreadable-%2.json").arg(slot).arg(stamp));
    for (int i = 2; QFileInfo::exists(path); ++i)
        path = QDir(m_path).filePath(QStringLiteral("autosave-%1.unreadable-%2-%3.json").arg(slot).arg(stamp).arg(i));
    return path;
}

QList<int> AutosaveDirectory::slotsWithFiles() const
{
    static const QRegularExpression name(QStringLiteral("^autosave-(\\d+)\\.json$"));
    QList<std::pair<QDateTime, int>> found;
    for (const QFileInfo &info : QDir(m_path).entryInfoList({QStringLiteral("autosave-*.json")}, QDir::Files)) {
        const auto match = name.match(info.fileName());
        if (match.hasMatch())
            found.append({info.lastModified(), match.captured(1).toInt()});
    }
    std::sort(found.begin(), found.end());
    QList<int> result;
    for (const auto &f : found)
        result.append(f.second);
    return result;
}

std::unique_ptr<QLockFile> AutosaveDirectory::tryLock(int slot) const
{
    auto lock = std::make_unique<QLockFile>(lockPath(slot));
    // Only a dead holder makes a lock stale, however old it is: an instance may run for days.
    lock->setStaleLockTime(0);
    return lock->tryLock(0) ? std::move(lock) : nullptr;
}

std::pair<int, std::unique_ptr<QLockFile>> AutosaveDirectory::claimFreeSlot() const
{
    for (int slot = 1; slot <= kMaxSlots; ++slot) {
        auto lock = tryLock(slot);
        // Locked first, then checked: a file in a slot we could lock was left for recovery.
        if (lock && !QFileInfo::exists(filePath(slot)))
            return {slot, std::move(lock)};
    }
    return {-1, nullptr};
}

bool AutosaveDirectory::ensureExists(QString *error) const
{
    if (files::makePrivatePath(m_path)) // 0700: the routes are the operator's
        return true;
    if (error)
        *error = QCoreApplication::translate("AutosaveDirectory", "Cannot create the autosave folder %1").arg(m_path);
    return false;
}

} // namespace sortie::client
