// TelemetryStore ingest throughput: values/s into the ring buffers, one at a time and by batch, and
// the same through Vehicle::ingest (last values, stale bits, coalesced notification, history).
#include "TelemetryStore.h"
#include "Vehicle.h"

#include <QCoreApplication>

#include <chrono>
#include <cstdio>
#include <ctime>

using namespace sortie::vehicle;

namespace {

template<typename F>
void measure(const char *name, size_t values, F &&body)
{
    const std::clock_t cpu = std::clock();
    body();
    const double seconds = double(std::clock() - cpu) / CLOCKS_PER_SEC;
    std::printf("%-34s %zu values in %.3f s CPU: %.1f million values/s\n", name, values, seconds, double(values) / seconds / 1e6);
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    constexpr size_t kValues = 50'000'000;
    constexpr size_t kFields = 16;
    std::printf("TelemetryStore, %zu fields x %zu samples each (capacity 18000 per field, %zu KiB each)\n", kFields, kValues / kFields,
                TelemetryStore::memoryBytesPerField(TelemetryStore::kDefaultCapacity) / 1024);

    TelemetryStore store;
    measure("TelemetryStore::ingest(field, ...)", kValues, [&] {
        for (size_t i = 0; i < kValues; ++i)
            store.ingest(TelemetryField(i % kFields), int64_t(i / kFields), double(i));
    });

    TelemetryStore batched;
    TelemetryBatch batch(kFields);
    measure("TelemetryStore::ingest(batch of 16)", kValues, [&] {
        for (size_t i = 0; i < kValues / kFields; ++i) {
            for (size_t f = 0; f < kFields; ++f)
                batch[f] = {TelemetryField(f), double(i), int64_t(i)};
            batched.ingest(batch);
        }
    });

    Vehicle vehicle(nullptr);
    constexpr size_t kVehicleValues = 10'000'000;
    measure("Vehicle::ingest(batch of 16)", kVehicleValues, [&] {
        for (size_t i = 0; i < kVehicleValues / kFields; ++i) {
            for (size_t f = 0; f < kFields; ++f)
                batch[f] = {TelemetryField(f), double(i), int64_t(i)};
            vehicle.ingest(batch);
        }
    });
    std::printf("history memory: %.1f MiB for %zu fields; telemetryChanged emitted %llu times\n",
                double(store.memoryBytes()) / (1024 * 1024), kFields, static_cast<unsigned long long>(vehicle.telemetryNotifications()));
    return store.series(TelemetryField::Latitude).size() == 18000 ? 0 : 1;
}
