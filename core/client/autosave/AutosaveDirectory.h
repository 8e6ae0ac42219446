#pragma once

#include <QList>
#include <QLockFile>
#include <QString>

#include <memory>

namespace sortie::client {

// Where autosaves live and how they are named. Each running instance owns a numbered slot:
// autosave-<n>.lock (a QLockFile held while it runs) and autosave-<n>.json (its working route).
// A slot whose file exists but whose lock nobody holds is an instance that crashed, or quit with
// edits it never saved. One discarded autosave is kept as autosave-discarded.json.
class AutosaveDirectory
{
public:
    explicit AutosaveDirectory(QString path);

    QString path() const { return m_path; }
    QString filePath(int slot) const;
    QString lockPath(int slot) const;
    QString discardedPath() const;
    // Where an unreadable file is moved: beside it, a new name each time (never overwritten).
    QString corruptPath(int slot) const;
    // Slots that have an autosave file, oldest file first.
    QList<int> slotsWithFiles() const;
    // The slot's lock if no live process holds it (a dead holder's stale lock is taken over), else null.
    std::unique_ptr<QLockFile> tryLock(int slot) const;
    // The first slot with no file whose lock is free, locked; -1 and null when none is.
    std::pair<int, std::unique_ptr<QLockFile>> claimFreeSlot() const;
    bool ensureExists(QString *error) const;

    static constexpr int kMaxSlots = 64;

private:
    QString m_path;
};

} // namespace sortie::client
