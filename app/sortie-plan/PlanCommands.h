#pragma once

#include <QStringList>
#include <QTextStream>

namespace sortie::plan {

// Exit codes: 0 done; 1 bad usage or a file that cannot be read or written; 2 the route has
// validation errors (stats) or the save was refused because of them (convert, scan), or two routes
// come too close (conflicts).
enum Exit { Ok = 0, Failure = 1, ValidationErrors = 2 };

struct Streams
{
    QTextStream &out;
    QTextStream &err;
};

int runConvert(const QStringList &args, Streams io);
int runStats(const QStringList &args, Streams io);
int runScan(const QStringList &args, Streams io);
// The rest of a route stopped half-way (docs/resume.md), from the last photo or a battery change.
int runResume(const QStringList &args, Streams io);

} // namespace sortie::plan
