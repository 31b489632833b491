// File checks shared by the tests that run writers: whether a file exists, and the temporaries a
// write may have left behind.
#ifndef DISTORTION_OPTIMIZATION_TEST_FILES_H
#define DISTORTION_OPTIMIZATION_TEST_FILES_H

#include <cstddef>
#include <fstream>
#include <string>

#include <dirent.h>

namespace test_files {

inline bool exists(const std::string& path) { return std::ifstream(path).good(); }

// The hidden temporaries of a write of `path` (".name.XXXXXX..."), which must not outlive it.
inline std::size_t leftovers(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "./" : path.substr(0, slash + 1);
  const std::string prefix = "." + path.substr(slash == std::string::npos ? 0 : slash + 1) + ".";
  std::size_t count = 0;
  if(DIR* d = opendir(folder.c_str())) {
    while(dirent* e = readdir(d)) count += std::string(e->d_name).rfind(prefix, 0) == 0;
    closedir(d);
  }
  return count;
}

} // namespace test_files

#endif // DISTORTION_OPTIMIZATION_TEST_FILES_H
