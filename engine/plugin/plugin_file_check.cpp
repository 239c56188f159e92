#include "plugin/plugin_file_check.h"

#include <elf.h>

#include <cstring>
#include <optional>
#include <string>
#include <string_view>

#include "plugin/plugin_api.h"
#include "util/file_read.h"

namespace penumbra::plugin {

namespace {

// A plugin is code plus its graph beside it; 1 GiB is far beyond any (ours are under 1 MB).
constexpr std::size_t kMaxPluginFileBytes = std::size_t{1} << 30;

#if defined(__x86_64__)
constexpr Elf64_Half kHostMachine = EM_X86_64;
#elif defined(__aarch64__)
constexpr Elf64_Half kHostMachine = EM_AARCH64;
#else
#error "plugin_file_check: add this CPU's ELF machine number"
#endif

// `count` records of `size` bytes at `offset` inside a file of `file_size` bytes, without
// overflow.
bool lies_inside(std::uint64_t offset, std::uint64_t count, std::uint64_t size, std::uint64_t file_size) {
  if (size != 0 && count > file_size / size) return false;
  return offset <= file_size && count * size <= file_size - offset;
}

class ElfFile {
 public:
  explicit ElfFile(std::string_view bytes) : bytes_(bytes) {}

  // Empty when the file is a whole shared library for this machine, else why not.
  std::string problem() {
    if (bytes_.size() < sizeof(Elf64_Ehdr) || std::memcmp(bytes_.data(), ELFMAG, SELFMAG) != 0)
      return "not a shared library (no ELF header)";
    std::memcpy(&header_, bytes_.data(), sizeof header_);
    if (header_.e_ident[EI_CLASS] != ELFCLASS64) return "not a 64-bit library (built for another machine?)";
    if (header_.e_ident[EI_DATA] != ELFDATA2LSB) return "a big-endian library (built for another machine)";
    if (header_.e_type != ET_DYN) return "not a shared library (ELF type " + std::to_string(header_.e_type) + ")";
    if (header_.e_machine != kHostMachine)
      return "built for another CPU (ELF machine " + std::to_string(header_.e_machine) + ")";
    const std::uint64_t size = bytes_.size();
    if (header_.e_phentsize != sizeof(Elf64_Phdr) ||
        !lies_inside(header_.e_phoff, header_.e_phnum, sizeof(Elf64_Phdr), size))
      return truncated("its program headers");
    for (Elf64_Half i = 0; i < header_.e_phnum; ++i) {
      Elf64_Phdr ph;
      std::memcpy(&ph, bytes_.data() + header_.e_phoff + i * sizeof ph, sizeof ph);
      if (!lies_inside(ph.p_offset, 1, ph.p_filesz, size)) return truncated("segment " + std::to_string(i));
    }
    if (header_.e_shnum == 0) return {};
    if (header_.e_shentsize != sizeof(Elf64_Shdr) ||
        !lies_inside(header_.e_shoff, header_.e_shnum, sizeof(Elf64_Shdr), size))
      return truncated("its section headers");
    for (Elf64_Half i = 0; i < header_.e_shnum; ++i) {
      const Elf64_Shdr sh = section(i);
      if (sh.sh_type != SHT_NOBITS && !lies_inside(sh.sh_offset, 1, sh.sh_size, size))
        return truncated("section " + std::to_string(i));
    }
    if (header_.e_shstrndx >= header_.e_shnum) return "its section name table is missing";
    return {};
  }

  // The bytes of the section called `name`, if there is one (after problem() returned empty).
  std::optional<std::string_view> section_bytes(std::string_view name) const {
    if (header_.e_shnum == 0) return std::nullopt;
    const Elf64_Shdr names = section(header_.e_shstrndx);
    const std::string_view table = bytes_.substr(names.sh_offset, names.sh_size);
    for (Elf64_Half i = 0; i < header_.e_shnum; ++i) {
      const Elf64_Shdr sh = section(i);
      if (sh.sh_name >= table.size() || sh.sh_type == SHT_NOBITS) continue;
      const std::string_view rest = table.substr(sh.sh_name);
      if (rest.substr(0, rest.find('\0')) == name) return bytes_.substr(sh.sh_offset, sh.sh_size);
    }
    return std::nullopt;
  }

 private:
  std::string truncated(const std::string& part) const {
    return "the file is truncated or damaged: " + part + " lie past its end (" + std::to_string(bytes_.size()) +
           " bytes); rebuild or copy it again";
  }

  Elf64_Shdr section(Elf64_Half i) const {
    Elf64_Shdr sh;
    std::memcpy(&sh, bytes_.data() + header_.e_shoff + i * sizeof sh, sizeof sh);
    return sh;
  }

  std::string_view bytes_;
  Elf64_Ehdr header_{};
};

}  // namespace

Result<int> read_plugin_abi_version(const std::filesystem::path& file) {
  auto fail = [&](std::string message) {
    Error e = make_error(std::move(message));
    e.file = file.string();
    return e;
  };
  Result<std::string> bytes = read_file_whole(file.string(), kMaxPluginFileBytes);
  if (!bytes) return bytes.error();
  ElfFile elf(*bytes);
  if (std::string why = elf.problem(); !why.empty()) return fail("cannot load plugin: " + why);
  const std::optional<std::string_view> note = elf.section_bytes(kPluginAbiSection);
  const std::string_view prefix = kPluginAbiNotePrefix;
  if (!note || !note->starts_with(prefix))
    return fail(std::string("not a Penumbra plugin: it has no ") + kPluginAbiSection +
                " section with its ABI version (add PENUMBRA_PLUGIN(register_fn) from plugin/plugin_api.h)");
  int version = 0;
  size_t digits = 0;
  for (char c : note->substr(prefix.size())) {
    if (c < '0' || c > '9' || digits == 6) break;
    version = version * 10 + (c - '0');
    ++digits;
  }
  if (digits == 0) return fail(std::string("its ") + kPluginAbiSection + " section holds no version number");
  return version;
}

}  // namespace penumbra::plugin
