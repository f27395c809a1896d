// Tasks handed out by root to whichever rank of the job is free, root included: a distributed --compare's
// reference halves and rows (docs/SCALING.md). Root keeps the queue; a free rank asks (Tag::Ask), gets the next
// task's description (Tag::Task), runs it and sends its bytes back (Tag::Result); root runs tasks of its own
// between serving the others, whose messages it takes before each batch of its renders. Data every task needs
// (the reference) goes to every rank once (Tag::Share), before the tasks that need it: messages between two
// ranks arrive in the order sent.
//
// The pool lives inside a part of the job (Cluster/SplitRender.h) and leaves its end to it: a Stop, or on root
// another rank's failure or cancel, cancels the part's RenderControl, and every wait here returns then.
#pragma once

#include <cstddef>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "Cluster/Job.h"
#include "Cluster/SplitRender.h"
#include "Render/RenderControl.h"

namespace rt::cluster
{
struct Task
{
    std::size_t index = 0; // in the order root added the tasks, from 0
    std::string description;
};

class TaskPool
{
  public:
    /// The pool of this rank's part `split`, whose control `control` is (the waits end when it is cancelled).
    /// Every rank makes one. Precondition: the part was made without progress messages.
    TaskPool(Job& job, SplitRender& split, RenderControl& control);
    ~TaskPool();
    TaskPool(const TaskPool&) = delete;
    TaskPool& operator=(const TaskPool&) = delete;

    /// Root: appends a task and hands it at once to a rank that is waiting for one. Returns its index.
    std::size_t add(std::string description);
    /// Root: sends `bytes` to every other rank, before any task added later, serving meanwhile. False when the
    /// part was cancelled first (a rank that failed receives nothing more).
    bool share(const std::string& bytes);
    /// Root: takes the messages that have arrived (also done before each batch of root's renders).
    void serve();
    /// Root: waits, serving, until every task handed to another rank has sent its result. False when the part
    /// was cancelled first.
    bool drain();
    /// Root: no task will be added; tells every other rank, as it asks, that none is left, and waits until each
    /// has been told (a rank asks once more after its last task), so that no Ask comes after the pool. False
    /// when the part was cancelled first (the others are stopped then).
    bool close();
    /// Root: the results that came from the other ranks since the last call, as (task, rank, bytes), in the
    /// order they came.
    struct Result
    {
        std::size_t task = 0;
        int rank = 0;
        std::string bytes;
    };
    std::vector<Result> takeResults();

    /// The next task for this rank: on root the queue's next, or none when it is empty (tasks handed out may
    /// still run elsewhere: drain); elsewhere root's answer to an Ask, waited for, or none when none is left or
    /// the part was cancelled. Shares that come meanwhile go to `onShare`. A rank other than root asks for its
    /// next task as it takes one, so that the answer, which root gives between the batches of its own renders,
    /// is there when this one ends: a rank holds at most one task besides the one it runs.
    std::optional<Task> next();
    /// A rank other than root: sends root the result of `task`, serving meanwhile (root takes it between the
    /// batches of its own renders). False when the part was cancelled first.
    bool sendResult(std::size_t task, const std::string& bytes);
    void onShare(std::function<void(std::string)> handler) { m_onShare = std::move(handler); }

    /// Tasks handed to another rank whose result has not come.
    std::size_t outstanding() const { return m_outstanding; }

  private:
    void take(const Message& m);
    void handOut();
    bool sendServing(int to, Tag tag, std::string bytes);
    /// Serves until `done`; false when the part was cancelled first (or meanwhile).
    bool serveUntil(const std::function<bool()>& done);

    Job& m_job;
    SplitRender& m_split;
    RenderControl& m_control;
    // Root:
    std::vector<std::string> m_tasks; // every task added, by index
    std::deque<std::size_t> m_queue; // not handed out yet
    std::deque<int> m_waiting; // ranks that asked and have no task yet
    std::vector<Result> m_results;
    std::size_t m_outstanding = 0;
    bool m_closed = false;
    int m_toldNone = 0; // ranks told that no task is left
    // Other ranks:
    void ask();
    std::deque<std::optional<Task>> m_answers; // root's answers not taken yet (a task, or none left)
    bool m_asking = false; // an Ask is unanswered
    std::function<void(std::string)> m_onShare;
};
} // namespace rt::cluster
