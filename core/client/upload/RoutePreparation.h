#pragma once

#include "MissionUploader.h"
#include "VehicleFleet.h"
#include "VehicleTypes.h"

#include <QObject>
#include <QPointer>
#include <QStringList>

namespace sortie::client {

class RouteDocument;

// The open route made ready for the vehicle that will fly it. The operator chooses the vehicle
// once; Process shows what that vehicle would fly, through its own link's prepareMission (the UgCS
// server processes the route against the vehicle's profile; a VCI vehicle's route is expanded here),
// and sends nothing; Upload hands the route to the one MissionUploader, which prepares it the same
// way before it goes up, so the preview is what flies. "Save, then upload" asks the route library
// (MissionController) to save first: saveRequested(), then routeSaved().
class RoutePreparation : public QObject
{
    Q_OBJECT
    // The vehicles a route can be prepared for, HCI and VCI (the chooser's model: vehicleId role).
    Q_PROPERTY(sortie::client::VehicleFleet *fleet READ fleet NOTIFY fleetChanged)
    // The chosen vehicle's `vehicleId` ("HCI:7", "VCI:vci-1"); empty: none chosen.
    Q_PROPERTY(QString vehicleId READ vehicleId WRITE setVehicleId NOTIFY vehicleIdChanged)
    Q_PROPERTY(sortie::client::MissionUploader *uploader READ uploader CONSTANT)
    Q_PROPERTY(bool processing READ isProcessing NOTIFY processingChanged)
    // The last preview: how many points the vehicle would fly (-1: none yet), what the preparation said.
    Q_PROPERTY(int previewCount READ previewCount NOTIFY previewChanged)
    Q_PROPERTY(QStringList notices READ notices NOTIFY previewChanged)
    Q_PROPERTY(QString message READ message NOTIFY messageChanged)

public:
    explicit RoutePreparation(RouteDocument *document, QObject *parent = nullptr);

    VehicleFleet *fleet() const { return m_fleet; }
    void setFleet(VehicleFleet *fleet); // not owned
    QString vehicleId() const { return m_vehicleId; }
    void setVehicleId(const QString &vehicleId);
    MissionUploader *uploader() { return &m_uploader; }
    bool isProcessing() const { return m_processing; }
    int previewCount() const { return m_hasPreview ? int(m_preview.items.size()) : -1; }
    const vehicle::PreparedMission &preview() const { return m_preview; }
    QStringList notices() const { return m_preview.notices; }
    QString message() const { return m_message; }

    Q_INVOKABLE void process();
    // Validated, prepared, under the vehicle's lock, verified: the uploader's pipeline.
    Q_INVOKABLE void upload();
    // The answer "save, then upload" to the uploader's question about unsaved edits.
    Q_INVOKABLE void saveAndUpload();
    // The library saved the route (its `saved` signal): an upload waiting for that goes on.
    void routeSaved();

signals:
    void fleetChanged();
    void vehicleIdChanged();
    void processingChanged();
    void previewChanged();
    void messageChanged();
    void saveRequested();
    void uploaded(const QString &vehicleId);

private:
    vehicle::Vehicle *chosen(const QString &doing);
    void setMessage(const QString &message);
    void setPreview(vehicle::PreparedMission preview, bool has);

    RouteDocument *m_document;
    QPointer<VehicleFleet> m_fleet;
    QString m_vehicleId;
    MissionUploader m_uploader;
    QString m_uploadTarget;
    bool m_uploadAfterSave = false;
    bool m_processing = false;
    int m_run = 0; // a newer Process (or a changed route) makes an older answer stale
    vehicle::PreparedMission m_preview;
    bool m_hasPreview = false;
    QString m_message;
};

} // namespace sortie::client
