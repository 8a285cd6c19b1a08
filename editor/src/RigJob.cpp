#include <lacrima/editor/RigJob.h>

#include <lacrima/playback/HeadRig.h>

#include <QMetaObject>
#include <QThread>

#include <atomic>
#include <exception>

namespace lacrima::editor {

namespace {

// Thrown from a superseded job's progress callback to unwind its rigging early. Never escapes
// the worker and is never reported.
struct Superseded {};

}  // namespace

// What the workers and the GUI thread share: the newest generation (a worker whose generation
// is older has been superseded and stops at its next progress report).
struct RigJob::Shared {
  std::atomic<quint64> newest{0};
};

RigJob::RigJob(QObject* parent) : QObject(parent), shared_(std::make_shared<Shared>()) {}

RigJob::~RigJob() {
  // No generation is newest any more: running jobs stop at their next progress report. Results
  // they post afterwards are queued to this object and discarded with it.
  shared_->newest = ~quint64{0};
  for (QThread* thread : threads_) {
    thread->wait();
    delete thread;
  }
}

bool RigJob::running() const { return running_; }

void RigJob::start(Work work) {
  reapFinishedThreads();
  const quint64 generation = ++newest_;
  shared_->newest = generation;
  running_ = true;

  // The worker holds the shared state, not `this`, for its cancellation check; `this` is only
  // used as the context of queued calls, which Qt drops if the RigJob is gone (it is not: the
  // destructor waits for the thread).
  std::shared_ptr<Shared> shared = shared_;
  QThread* thread = QThread::create([this, shared, generation, work = std::move(work)] {
    const auto report = [this, shared, generation](double fraction, std::string_view stage) {
      if (shared->newest != generation) throw Superseded{};
      const QString text = QString::fromUtf8(stage.data(), static_cast<qsizetype>(stage.size()));
      QMetaObject::invokeMethod(
          this, [this, generation, fraction, text] { deliverProgress(generation, fraction, text); },
          Qt::QueuedConnection);
    };
    std::shared_ptr<playback::HeadRig> rig;
    QString error;
    try {
      rig = work(report);
      if (!rig) error = tr("rigging produced no head");
    } catch (const Superseded&) {
      return;  // nobody is waiting for this one
    } catch (const std::exception& e) {
      error = QString::fromUtf8(e.what());
    } catch (...) {
      error = tr("rigging failed with an unknown error");
    }
    if (shared->newest != generation) return;  // superseded while finishing: drop it here
    QMetaObject::invokeMethod(
        this,
        [this, generation, rig = std::move(rig), error]() mutable {
          deliverResult(generation, std::move(rig), error);
        },
        Qt::QueuedConnection);
  });
  thread->setObjectName(QStringLiteral("RigJob"));
  threads_.push_back(thread);
  thread->start();
}

void RigJob::deliverProgress(quint64 generation, double fraction, const QString& stage) {
  if (generation != newest_ || !running_) return;
  emit progress(fraction, stage);
}

void RigJob::deliverResult(quint64 generation, std::shared_ptr<playback::HeadRig> rig,
                           const QString& error) {
  reapFinishedThreads();
  // The worker checked before posting, but a start() may have come in since.
  if (generation != newest_) return;
  running_ = false;
  if (rig)
    emit finished(std::move(rig));
  else
    emit failed(error);
}

void RigJob::reapFinishedThreads() {
  auto kept = threads_.begin();
  for (QThread* thread : threads_) {
    if (thread->isFinished()) {
      thread->wait();  // returns at once; makes sure run() has fully returned
      delete thread;
    } else {
      *kept++ = thread;
    }
  }
  threads_.erase(kept, threads_.end());
}

}  // namespace lacrima::editor
