// libFuzzer target for the command-line tool's parser: the input, split at NUL bytes, is the
// argument list. Any input must parse or raise the tool's Usage_error (exit status 2); another
// exception, a crash, a hang or a sanitizer report is a bug. Run in a folder of its own: the
// parser only stat()s the paths it is given, it never opens or writes them.

#include "../command_line.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::vector<std::string> words = {"distortion_optimizer"};
  std::string word;
  for(std::size_t i = 0; i < size; ++i) {
    if(data[i] == 0) { words.push_back(word); word.clear(); }
    else word.push_back(static_cast<char>(data[i]));
  }
  words.push_back(word);
  std::vector<char*> argv;
  for(std::string& w : words) argv.push_back(&w[0]);
  try {
    distortion_optimizer::parse(static_cast<int>(argv.size()), argv.data());
  } catch(const distortion_optimizer::Usage_error&) {
  }
  return 0;
}
