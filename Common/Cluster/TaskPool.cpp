#include "Cluster/TaskPool.h"

#include <chrono>
#include <thread>

#include "Check.h"
#include "Error.h"

namespace rt::cluster
{
namespace
{
/// "index\nbytes": how a task and a result name the task they are.
std::string numbered(std::size_t index, const std::string& bytes)
{
    return std::to_string(index) + "\n" + bytes;
}

std::pair<std::size_t, std::string> unnumbered(const std::string& text)
{
    const std::size_t line = text.find('\n');
    if (line == std::string::npos)
        throw Error("MPI: a task's message has no index line");
    return {std::stoull(text.substr(0, line)), text.substr(line + 1)};
}

void pause()
{
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}
} // namespace

TaskPool::TaskPool(Job& job, SplitRender& split, RenderControl& control)
    : m_job(job), m_split(split), m_control(control)
{
    m_split.setOtherMessages([this](const Message& m) { take(m); });
}

TaskPool::~TaskPool()
{
    m_split.setOtherMessages({});
}

std::size_t TaskPool::add(std::string description)
{
    RT_CHECK(m_job.root() && !m_closed);
    m_tasks.push_back(std::move(description));
    m_queue.push_back(m_tasks.size() - 1);
    handOut();
    return m_tasks.size() - 1;
}

bool TaskPool::share(const std::string& bytes)
{
    RT_CHECK(m_job.root());
    for (int r = 1; r < m_job.size(); ++r)
        if (!sendServing(r, Tag::Share, bytes))
            return false;
    return true;
}

bool TaskPool::sendServing(int to, Tag tag, std::string bytes)
{
    serve(); // an End that came already: a failed rank receives nothing
    if (m_control.cancelRequested())
        return false;
    return m_job.sendWhile(to, tag, std::move(bytes), [this] {
        serve();
        return !m_control.cancelRequested();
    });
}

void TaskPool::serve()
{
    m_split.beforeBatch();
}

bool TaskPool::serveUntil(const std::function<bool()>& done)
{
    while (!done())
    {
        if (m_control.cancelRequested())
            return false;
        serve();
        if (!done())
            pause();
    }
    return !m_control.cancelRequested();
}

bool TaskPool::drain()
{
    return serveUntil([this] { return m_outstanding == 0; });
}

bool TaskPool::close()
{
    m_closed = true;
    handOut();
    return serveUntil([this] { return m_toldNone >= m_job.size() - 1; });
}

std::vector<TaskPool::Result> TaskPool::takeResults()
{
    std::vector<Result> results;
    results.swap(m_results);
    return results;
}

std::optional<Task> TaskPool::next()
{
    if (m_job.root())
    {
        serve();
        if (m_control.cancelRequested() || m_queue.empty())
            return std::nullopt;
        const std::size_t index = m_queue.front();
        m_queue.pop_front();
        return Task{index, m_tasks[index]};
    }
    if (m_answers.empty() && !m_asking)
        ask();
    if (!serveUntil([this] { return !m_answers.empty(); }))
        return std::nullopt;
    std::optional<Task> answer = std::move(m_answers.front());
    m_answers.pop_front();
    if (answer && !m_asking)
        ask(); // the next one, while this one runs
    return answer;
}

void TaskPool::ask()
{
    m_job.send(0, Tag::Ask, {});
    m_asking = true;
}

bool TaskPool::sendResult(std::size_t task, const std::string& bytes)
{
    return sendServing(0, Tag::Result, numbered(task, bytes));
}

void TaskPool::take(const Message& m)
{
    switch (m.tag)
    {
    case Tag::Ask:
        m_waiting.push_back(m.from);
        handOut();
        break;
    case Tag::Result:
    {
        auto [task, bytes] = unnumbered(m.bytes);
        m_results.push_back({task, m.from, std::move(bytes)});
        RT_CHECK(m_outstanding > 0);
        --m_outstanding;
        break;
    }
    case Tag::Task:
        m_asking = false;
        if (m.bytes.empty())
            m_answers.emplace_back(std::nullopt);
        else
        {
            auto [index, description] = unnumbered(m.bytes);
            m_answers.emplace_back(Task{index, std::move(description)});
        }
        break;
    case Tag::Share:
        if (m_onShare)
            m_onShare(m.bytes);
        break;
    default:
        break;
    }
}

void TaskPool::handOut()
{
    while (!m_waiting.empty() && (!m_queue.empty() || m_closed))
    {
        const int rank = m_waiting.front();
        m_waiting.pop_front();
        if (m_queue.empty())
        {
            m_job.send(rank, Tag::Task, {});
            ++m_toldNone;
            continue;
        }
        const std::size_t index = m_queue.front();
        m_queue.pop_front();
        m_job.send(rank, Tag::Task, numbered(index, m_tasks[index]));
        ++m_outstanding;
    }
}
} // namespace rt::cluster
