// glossy.study's compiled part, _core._study (the package's glossy/_study.py is its front, with the reading
// of the results): a study file run as `glossy study` runs it (renderer/app/study_job.h), so the two write
// the same bytes into the same folder.
#include "materials/params/material_file.h"
#include "materials/core/input_error.h"
#include "renderer/app/option_specs.h"
#include "renderer/app/shard.h"
#include "renderer/app/study_job.h"
#include "renderer/python/background_job.h"
#include "renderer/python/module_support.h"

namespace glossy::python {

void bindStudies(py::module_& m) {
  m.def(
      "_study",
      [](const py::object& file, const py::object& output, const py::object& shard, bool analyse, const py::object& merlDir,
         const py::object& threads) {
        return guarded([&] {
          app::StudyRequest r;
          r.file = pathText(file);
          r.out = pathText(output);
          r.outName = "output";
          if (!shard.is_none()) {
            if (!py::isinstance<py::str>(shard)) throw InputError("shard: must be a string, 'i/N'");
            r.shard = shard.cast<std::string>();
            if (r.shard.empty()) throw InputError("shard: an empty string (None renders every sheet)");
          }
          r.analyseOnly = analyse;
          if (analyse && !r.shard.empty()) throw InputError("analyse: analyses the whole study, not a shard (drop shard)");
          try {
            (void)app::shardFrom(r.shard);  // checked here to name the keyword, not the command's --shard
          } catch (const InputError& e) {
            const std::string message = e.what();
            throw InputError(message.starts_with("--shard") ? "shard" + message.substr(7) : message);
          }
          if (!merlDir.is_none()) {
            r.merlDir = pathText(merlDir);
            if (r.merlDir.empty()) throw InputError("merl_dir: an empty path");
          }
          checkMerlDirs(r.merlDir, "merl_dir");  // as every command's --merl-dir: a folder, or refused
          if (!threads.is_none()) {
            if (!py::isinstance<py::int_>(threads) || py::isinstance<py::bool_>(threads))
              throw InputError("threads: must be a whole number");
            r.threads = int(checkedOption(app::options::kThreads, threads.cast<double>(), "threads"));
          }
          JobControl control;
          r.control = &control;
          const app::StudyRun run = runInterruptible(control, py::none(), [&] { return app::runStudy(r); });
          static constexpr const char* kEnded[] = {"analysed", "shard done", "busy", "incomplete"};
          return std::string(kEnded[int(run.ended)]);
        });
      },
      py::arg("file"), py::arg("output"), py::arg("shard") = py::none(), py::arg("analyse") = false, py::arg("merl_dir") = py::none(),
      py::arg("threads") = py::none(), "glossy.study's work: how it ended; glossy.study is the function to call.");
}

}  // namespace glossy::python
