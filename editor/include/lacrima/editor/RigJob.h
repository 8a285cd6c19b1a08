#pragma once
// Rigs a head on a worker thread so the window never freezes (the ICT head takes the better
// part of a second, a big scan longer). Results come back on the GUI thread as signals.
//
// Only the newest job speaks: start() while a job runs supersedes it, and the old job's
// result, failure and progress are dropped. A superseded job is also asked to stop early: its
// next progress report throws (caught here), so rigHead()/loadHeadRig() unwind at their next
// stage instead of finishing work nobody will look at. The destructor waits for every worker
// thread, so a Work function may safely reference objects that outlive the RigJob.
#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <string_view>
#include <vector>

class QThread;

namespace lacrima::playback {
struct HeadRig;
}

namespace lacrima::editor {

class RigJob : public QObject {
  Q_OBJECT
 public:
  // Builds the rig; called on a worker thread; `progress` may be called from there.
  using Work = std::function<std::unique_ptr<playback::HeadRig>(
      const std::function<void(double fraction, std::string_view stage)>& progress)>;

  explicit RigJob(QObject* parent = nullptr);
  ~RigJob() override;  // waits for a running job, drops its result

  // A newer start supersedes the running one: only the newest job's result or failure is ever
  // emitted.
  void start(Work work);
  // Whether the newest job has not delivered its result or failure yet.
  bool running() const;

 signals:
  void progress(double fraction, const QString& stage);   // queued to the GUI thread
  void finished(std::shared_ptr<playback::HeadRig> rig);  // the newest job's rig
  void failed(const QString& message);                    // FileError text etc.

 private:
  // Called on the GUI thread (queued from the worker) for job `generation`.
  void deliverProgress(quint64 generation, double fraction, const QString& stage);
  void deliverResult(quint64 generation, std::shared_ptr<playback::HeadRig> rig,
                     const QString& error);
  void reapFinishedThreads();

  struct Shared;
  std::shared_ptr<Shared> shared_;  // the newest generation, read by the workers
  quint64 newest_ = 0;              // GUI thread's copy
  bool running_ = false;
  std::vector<QThread*> threads_;  // owned; deleted once finished (and in the destructor)
};

}  // namespace lacrima::editor
