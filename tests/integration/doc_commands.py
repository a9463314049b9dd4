#!/usr/bin/python3
"""doc_commands: every `dream ...` command the documentation shows is one the command line accepts.

Reads the tracked Markdown files (git ls-files '*.md'; without git, every .md outside build
folders) and takes each command line that invokes dream (`dream`, `./build/dream`,
`$DREAM/build/dream`, `~/dream/bin/dream`, ...) from fenced code blocks, four-space indented
blocks and inline code spans; then the `Example:` lines of dream's own --help texts. For each
it checks, against `dream [SUB [SUBSUB]] --help`:

- the subcommand (and `log`'s sub-subcommand) exists;
- every option it passes is one that subcommand (or dream itself: -q, -v) accepts;
- every file it names under config/ or docs/examples/ exists; in a code block after
  `cd docs/examples/...`, so does every relative .yaml file it names.

Placeholders (`CONFIG`, `RUN`, `config/<name>.yaml`) are allowed where they stand for
positionals; the options beside them are still checked. Before the docs, the checker must
reject three synthetic lines (an unknown option, an unknown subcommand, a missing config), so
a checker that accepts everything fails here.

Usage: doc_commands.py --dream BIN --source DIR
"""

import os
import re
import shlex
import subprocess
import sys

from dreamtest import arguments, check, main

SEPARATORS = {";", "&&", "||", "|", "&", "(", ")", "|&", ";;"}
WRAPPERS = {"nice", "sudo", "exec", "env"}
PLACEHOLDER = re.compile(r"[<>*{}$\[\]]|\.\.\.")


def markdown_files(source):
    try:
        listed = subprocess.run(["git", "-C", source, "ls-files", "*.md"], stdout=subprocess.PIPE,
                                stderr=subprocess.DEVNULL, text=True, timeout=30)
        if listed.returncode == 0 and listed.stdout.strip():
            return sorted(listed.stdout.split())
    except (OSError, subprocess.TimeoutExpired):
        pass
    found = []
    for folder, dirs, files in os.walk(source):
        dirs[:] = [d for d in dirs if not d.startswith((".", "build"))]
        found += [os.path.relpath(os.path.join(folder, f), source) for f in files if f.endswith(".md")]
    return sorted(found)


def snippets(text):
    """(line number, text, (kind, block)) of every shell-like piece: kind 'block' (a line of a
    fenced or indented block; `block` numbers the block, so that a `cd` applies to the lines after
    it in the same block) or 'inline' (a code span, which may run over a line break)."""
    out = []
    paragraph = []  # (line number, line) of the prose being read

    def end_paragraph():
        joined, starts = "", []
        for number, line in paragraph:
            starts.append((len(joined), number))
            joined += line + " "
        for match in re.finditer(r"`([^`]+)`", joined):
            number = [n for offset, n in starts if offset <= match.start()][-1]
            out.append((number, match.group(1).strip(), ("inline", None)))
        paragraph.clear()

    fence = None
    shell_language = False
    block = 0
    previous_blank = True
    in_indented = False
    for number, line in enumerate(text.split("\n"), 1):
        stripped = line.strip()
        if fence is not None:
            if stripped.startswith(fence):
                fence = None
                block += 1
            elif shell_language:
                out.append((number, stripped, ("block", block)))
            continue
        match = re.match(r"\s*(```+|~~~+)\s*([\w+-]*)", line)
        if match:
            end_paragraph()
            fence = match.group(1)
            shell_language = match.group(2) in ("", "sh", "bash", "shell", "console")
            block += 1
            in_indented = False
        elif line.startswith("    ") and stripped and (previous_blank or in_indented) \
                and not re.match(r"[-*|]|\d+\.", stripped):
            end_paragraph()
            in_indented = True
            out.append((number, stripped, ("block", block)))
        else:
            if in_indented:
                block += 1
            in_indented = False
            if stripped:
                paragraph.append((number, stripped))
            else:
                end_paragraph()
        previous_blank = not stripped
    end_paragraph()
    return out


def tokens_of(line):
    """Shell tokens of one line (comments dropped); an unbalanced quote (a command continued on
    the next line) is closed at the end of the line."""
    if line.startswith("$ "):
        line = line[2:]
    for closing in ("", "'", '"'):
        try:
            lexer = shlex.shlex(line + closing, posix=True, punctuation_chars=";&|()")
            lexer.whitespace_split = True
            return list(lexer)
        except ValueError:
            continue
    return []


def segments(tokens):
    """Simple commands: the tokens between separators, with `sh -c SCRIPT` opened up."""
    current = []
    for token in tokens + [";"]:
        if token in SEPARATORS:
            if current:
                yield from simple_commands(current)
            current = []
        else:
            current.append(token)


def simple_commands(words):
    """Strips environment assignments and wrappers (time, timeout N, /usr/bin/time -f FMT,
    unshare -n); `sh -c SCRIPT` yields the script's own commands."""
    i = 0
    while i < len(words):
        word = words[i]
        base = os.path.basename(word)
        if re.match(r"[A-Za-z_][A-Za-z0-9_]*=", word) or base in WRAPPERS:
            i += 1
        elif base == "timeout":
            i += 2
        elif base == "time" or word == "/usr/bin/time":
            i += 1
            while i < len(words) and words[i].startswith("-"):
                i += 2 if words[i] in ("-f", "-o") else 1
        elif base == "unshare":
            i += 1
            while i < len(words) and words[i].startswith("-"):
                i += 1
        elif base in ("sh", "bash") and i + 2 < len(words) and words[i + 1] == "-c":
            yield from segments(tokens_of(words[i + 2]))
            return
        else:
            break
    if i < len(words):
        yield words[i:]


def is_dream(word):
    return os.path.basename(word) == "dream" and not word.startswith("(")


class Cli:
    """What `dream ... --help` says: subcommands and options, cached per command path."""

    def __init__(self, dream):
        self.dream = dream
        self.cache = {}

    def help(self, path):
        return self.help_and_text(path)[0]

    def help_and_text(self, path):
        if path not in self.cache:
            result = subprocess.run([self.dream, *path, "--help"], stdout=subprocess.PIPE,
                                    stderr=subprocess.STDOUT, text=True, timeout=30)
            check(result.returncode == 0, f"`dream {' '.join(path)} --help` exited {result.returncode}: "
                                          f"{result.stdout[-300:]}")
            self.cache[path] = (parse_help(result.stdout), result.stdout)
        return self.cache[path]

    def examples(self):
        """The `Example: dream ...` lines of dream's own help, as Markdown blocks to check like the docs."""
        texts = [self.help_and_text(())[1]]
        subcommands, _ = self.help(())
        for sub in sorted(subcommands):
            nested, _ = self.help((sub,))
            texts.append(self.help_and_text((sub,))[1])
            texts += [self.help_and_text((sub, inner))[1] for inner in sorted(nested)]
        lines = sorted({m for text in texts for m in re.findall(r"Example: (dream .*)", text)})
        return "".join(f"```\n{line}\n```\n" for line in lines)


def parse_help(text):
    """(subcommands, options) of a CLI11 help text."""
    subcommands, options = set(), set()
    section = None
    for line in text.split("\n"):
        if re.match(r"\S.*:$", line):
            section = line[:-1]
            continue
        if section == "Options":
            match = re.match(r"  (-[\w-]+(?:,-[\w-]+)*)", line)
            if match:
                options.update(match.group(1).split(","))
        elif section == "Subcommands":
            match = re.match(r"  ([a-z][\w-]*)", line)
            if match:
                subcommands.add(match.group(1))
    return subcommands, options


def option_names(word):
    """The option names in one word: `--out=X` -> --out, `--seed/--set` -> both, `-j2` -> -j."""
    names = []
    for part in word.split("/") if re.fullmatch(r"-[\w-]+(/-[\w-]+)+", word) else [word]:
        part = part.split("=", 1)[0]
        if re.fullmatch(r"-[A-Za-z]\d+", part):
            part = part[:2]
        names.append(part)
    return names


def check_command(cli, source, words, kind, cwd):
    """Problems of one dream invocation (words[0] is the dream executable); [] when none."""
    problems = []
    root_subcommands, root_options = cli.help(())
    args = [w.strip("[]") for w in words[1:]]
    args = [a for a in args if a]
    if not args:
        return problems
    if args[0].startswith("-"):
        for name in option_names(args[0]):
            if name not in root_options:
                problems.append(f"dream has no option {name}")
        return problems
    path = (args[0],)
    if args[0] not in root_subcommands:
        if kind == "inline" and not re.fullmatch(r"[a-z][\w-]*", args[0]):
            return problems  # prose in backticks, not a command
        return [f"dream has no subcommand '{args[0]}'"]
    rest = args[1:]
    subcommands, options = cli.help(path)
    if subcommands:
        if rest and not rest[0].startswith("-") and (rest[0] in subcommands or re.fullmatch(r"[a-z][\w-]*", rest[0])):
            # (dream sweep also takes a CONFIG path where its subcommands stand)
            if rest[0] not in subcommands:
                return [f"dream {args[0]} has no subcommand '{rest[0]}'"]
            path += (rest[0],)
            rest = rest[1:]
            subcommands, options = cli.help(path)
        elif kind == "block" and not rest:
            return [f"dream {args[0]} needs a subcommand ({', '.join(sorted(subcommands))})"]
    allowed = options | root_options
    for word in rest:
        if not word.startswith("-") or word == "-" or re.fullmatch(r"-\d[\d.]*", word):
            continue
        for name in option_names(word):
            if name not in allowed:
                problems.append(f"dream {' '.join(path)} has no option {name}")
    for word in rest:
        value = word.split("=", 1)[1] if word.startswith("-") and "=" in word else word
        if PLACEHOLDER.search(value):
            continue
        named = value[2:] if value.startswith("./") else value
        if named.startswith(("config/", "docs/examples/")):
            if not os.path.exists(os.path.join(source, named)):
                problems.append(f"{named} does not exist")
        elif cwd and re.fullmatch(r"[\w./-]+\.ya?ml", value) and not os.path.isabs(value):
            if not os.path.exists(os.path.join(source, cwd, value)):
                problems.append(f"{os.path.join(cwd, value)} does not exist (after cd {cwd})")
    return problems


def check_markdown(cli, source, name, text):
    """(number of dream commands, problems) of one Markdown text."""
    count, problems = 0, []
    cwd_of_block = {}
    for number, line, (kind, block) in snippets(text):
        for words in segments(tokens_of(line)):
            if kind == "block" and words[0] == "cd" and len(words) == 2:
                target = words[1]
                if not os.path.isabs(target) and not target.startswith(("~", "$")):
                    cwd_of_block[block] = os.path.normpath(os.path.join(cwd_of_block.get(block, ""), target))
                continue
            if not is_dream(words[0]):
                continue
            if kind == "inline" and (len(words) < 2 or not re.fullmatch(r"-{0,2}[a-z][\w-]*", words[1])):
                continue  # `dream` alone, or prose in backticks
            count += 1
            for problem in check_command(cli, source, words, kind, cwd_of_block.get(block)):
                problems.append(f"{name}:{number}: `{line}`: {problem}")
    return count, problems


def test(context, args):
    cli = Cli(args.dream)
    source = os.path.abspath(args.source)

    # The checker itself: each synthetic line must be refused, for the reason it was made up.
    made_up = [
        ("```\ndream run config/go_to_goal.yaml --no-such-option 3\n```\n", "has no option --no-such-option"),
        ("    ./build/dream frobnicate config/go_to_goal.yaml\n", "has no subcommand 'frobnicate'"),
        ("Run `dream sweep config/no_such_experiment.yaml --seeds 1-3`.\n",
         "config/no_such_experiment.yaml does not exist"),
        ("```\ndream log echo runs/x DREAM_POSES --limit 3 --pretty\n```\n", "dream log echo has no option --pretty"),
        ("```\ncd docs/examples/out_of_tree_controller\n~/dream/bin/dream run nothing_here.yaml\n```\n",
         "nothing_here.yaml does not exist"),
    ]
    for text, reason in made_up:
        count, problems = check_markdown(cli, source, "synthetic.md", text)
        check(count == 1 and any(reason in p for p in problems),
              f"the checker does not refuse {text.strip()!r} ({reason}): {count} commands, problems {problems}")
    count, problems = check_markdown(
        cli, source, "synthetic.md",
        "```\ndream run config/go_to_goal.yaml --seed 7 --set controller.max_speed_mps=0.1 -q  # ok\n```\n")
    check(count == 1 and not problems, f"the checker refuses a correct line: {problems}")

    total, all_problems = 0, []
    files = markdown_files(source)
    check(any(f == "README.md" for f in files), f"no README.md among the Markdown files of {source}: {files}")
    for name in files:
        with open(os.path.join(source, name), encoding="utf-8") as f:
            count, problems = check_markdown(cli, source, name, f.read())
        total += count
        all_problems += problems
    # The docs show well over a hundred dream commands; far fewer means the extraction broke.
    check(total >= 100, f"only {total} dream commands found in {len(files)} Markdown files")
    # dream's own --help shows examples too: they must be commands it accepts.
    count, problems = check_markdown(cli, source, "dream --help", cli.examples())
    check(count >= 10, f"only {count} examples in dream's --help texts")
    total += count
    all_problems += problems
    check(not all_problems, f"{len(all_problems)} documented dream command(s) the command line refuses:\n"
          + "\n".join(all_problems))
    print(f"{total} dream commands in {len(files)} Markdown files and dream's --help examples: "
          "every subcommand, option and path exists")


if __name__ == "__main__":
    parsed = arguments()
    main(lambda context: test(context, parsed))
