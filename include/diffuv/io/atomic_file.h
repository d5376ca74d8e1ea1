// diffuv: files that appear whole or not at all.
//
// Every file diffuv writes goes through `Atomic_output_file`: the text is
// written to a hidden temporary file next to the target, and renamed onto the
// target only once everything was written and flushed without error. A run
// that fails half-way (an exception, a full disk, a killed process) leaves the
// previous file, or no file, never a truncated one that a later step would
// read as valid.
#ifndef DIFFUV_IO_ATOMIC_FILE_H
#define DIFFUV_IO_ATOMIC_FILE_H

#include <diffuv/core/error.h>

#include <unistd.h> // getpid

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <memory>
#include <string>
#include <vector>
#include <system_error>

namespace diffuv {

/// Writes a file through a temporary file that is renamed onto the target by
/// `commit()`, so that the target is either the old file or the complete new one.
///
/// The temporary file is `<dir>/.<name>.tmp.<pid>`, in the folder of the
/// target: `std::rename` is atomic only within one file system. Two objects of
/// one process writing the same target at the same time would share it.
/// If `commit()` is not called (an exception unwinds, or an error was found),
/// the destructor removes the temporary file and the target is untouched.
///
/// The rename protects against a failure of the program, not against a power
/// loss (the data is not `fsync`ed).
class Atomic_output_file {
public:
  /// Creates the temporary file for `target`.
  /// \param target the path of the file to write; its folder must exist
  ///        (see `ensure_output_directory()`)
  /// \throws Output_error naming `target` if the temporary file cannot be
  ///         created (missing folder, no permission)
  explicit Atomic_output_file(const std::string& target)
    : target_(target), temporary_(temporary_path_for(target))
  {
    file_.open(temporary_, std::ios::out | std::ios::trunc | std::ios::binary);
    if(!file_.is_open()) {
      const int e = errno;
      throw Output_error(target_, "cannot create the temporary file " + temporary_ +
                                  " (" + std::strerror(e) + ")");
    }
  }

  Atomic_output_file(const Atomic_output_file&) = delete;
  Atomic_output_file& operator=(const Atomic_output_file&) = delete;

  /// Removes the temporary file if `commit()` did not rename it.
  ~Atomic_output_file()
  {
    if(!committed_) {
      file_.close();
      std::remove(temporary_.c_str()); // nothing to report from a destructor
    }
  }

  /// Returns the stream to write the content to.
  std::ostream& stream() { return file_; }

  /// Returns the path of the target file.
  const std::string& path() const { return target_; }

  /// Returns the path of the temporary file.
  const std::string& temporary_path() const { return temporary_; }

  /// Flushes and closes the temporary file and renames it onto the target.
  /// Does nothing if already committed.
  /// \throws Output_error naming the target if a write failed (disk full,
  ///         I/O error, a stream state set by the caller) or the rename fails;
  ///         the temporary file is then removed and the target is untouched
  void commit()
  {
    if(committed_)
      return;
    finish();
    if(std::rename(temporary_.c_str(), target_.c_str()) != 0) {
      const int e = errno;
      std::remove(temporary_.c_str());
      throw Output_error(target_, "cannot rename the temporary file " + temporary_ +
                                  " onto it (" + std::strerror(e) + ")");
    }
    committed_ = true;
  }

  /// Flushes and closes the temporary file, without renaming it (the first
  /// half of `commit()`: `Output_folder` finishes every file before renaming any).
  /// Does nothing if already finished.
  /// \throws Output_error naming the target if a write failed; the temporary
  ///         file is then removed
  void finish()
  {
    if(finished_)
      return;
    // A full disk shows up at the flush, or only at the close when the last
    // buffer is written: check the stream after both.
    file_.flush();
    const bool written = static_cast<bool>(file_);
    file_.close();
    if(!written || file_.fail()) {
      std::remove(temporary_.c_str());
      throw Output_error(target_, "writing failed (disk full or I/O error)");
    }
    finished_ = true;
  }

private:
  static std::string temporary_path_for(const std::string& target)
  {
    const std::filesystem::path p(target);
    const std::string name = "." + p.filename().string() + ".tmp." + std::to_string(::getpid());
    return (p.parent_path() / name).string();
  }

  std::string target_;
  std::string temporary_;
  std::ofstream file_;
  bool finished_ = false;
  bool committed_ = false;
};

/// Makes sure that `dir` is a folder diffuv can write into, creating it
/// (and its parents) if it does not exist.
///
/// Writability is tested by creating and removing a probe file, because
/// permission bits do not tell the whole story (read-only mounts, ACLs, root).
/// \param dir the folder; an empty string means the current folder
/// \throws Output_error naming `dir` if it exists and is not a folder, cannot
///         be created, or is not writable
inline void ensure_output_directory(const std::string& dir)
{
  namespace fs = std::filesystem;
  const fs::path p(dir.empty() ? std::string(".") : dir);
  std::error_code ec;
  const fs::file_status status = fs::status(p, ec);
  if(fs::exists(status)) {
    if(!fs::is_directory(status))
      throw Output_error(dir, "exists and is not a directory");
  } else {
    fs::create_directories(p, ec);
    if(ec)
      throw Output_error(dir, "cannot create the directory (" + ec.message() + ")");
  }

  const fs::path probe = p / (".diffuv_probe." + std::to_string(::getpid()));
  std::ofstream f(probe, std::ios::out | std::ios::trunc);
  if(!f.is_open())
    throw Output_error(dir, "the directory is not writable");
  f.close();
  fs::remove(probe, ec); // a leftover hidden probe file is harmless
}

/// The files a command writes into one folder, written all or none: each goes
/// to a temporary file first, and only when every one is complete are they all
/// renamed. A folder created here is removed again if nothing was committed.
class Output_folder {
public:
  /// Prepares `dir` (see `ensure_output_directory()`).
  /// \param inputs files the command reads, which no output may replace
  /// \throws Output_error as `ensure_output_directory()`
  explicit Output_folder(std::string dir, std::vector<std::string> inputs = {})
    : dir_(std::move(dir)), inputs_(std::move(inputs))
  {
    std::error_code ec;
    created_ = !std::filesystem::exists(dir_.empty() ? "." : dir_, ec);
    ensure_output_directory(dir_);
  }

  Output_folder(const Output_folder&) = delete;
  Output_folder& operator=(const Output_folder&) = delete;

  /// Removes the folder if this object created it and nothing was committed
  /// (only if empty: the temporary files are gone by then).
  ~Output_folder()
  {
    files_.clear();
    if(created_ && !committed_) {
      std::error_code ec;
      std::filesystem::remove(dir_, ec);
    }
  }

  /// Starts the file `name` in the folder and returns the stream to write it.
  /// \throws Output_error if the path is a folder, is one of the inputs, or cannot be created
  std::ostream& open(const std::string& name)
  {
    namespace fs = std::filesystem;
    const std::string path = (fs::path(dir_.empty() ? "." : dir_) / name).string();
    std::error_code ec;
    if(fs::is_directory(path, ec))
      throw Output_error(path, "is a directory");
    for(const std::string& input : inputs_)
      if(fs::exists(input, ec) && fs::equivalent(input, path, ec))
        throw Output_error(path, "would replace the input file " + input);
    files_.push_back(std::make_unique<Atomic_output_file>(path));
    return files_.back()->stream();
  }

  /// The path of each file opened, in order.
  std::vector<std::string> paths() const
  {
    std::vector<std::string> p;
    for(const auto& f : files_) p.push_back(f->path());
    return p;
  }

  /// Renames every file onto its target, once every one of them is complete:
  /// a write error (a full disk) in any file leaves the folder as it was.
  /// \throws Output_error naming the first file that fails
  void commit()
  {
    for(auto& f : files_) f->finish();
    for(auto& f : files_) f->commit();
    committed_ = true;
  }

private:
  std::string dir_;
  std::vector<std::string> inputs_;
  std::vector<std::unique_ptr<Atomic_output_file>> files_;
  bool created_ = false;
  bool committed_ = false;
};

} // namespace diffuv

#endif // DIFFUV_IO_ATOMIC_FILE_H
