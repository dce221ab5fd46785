#!/usr/bin/env python3
"""Structure figures for the issue "One declaration per study".

Usage: python3 scripts/metrics.py [--rev GITREV] [--json]

Reads the working tree (pruning target/, fuzz/, .git/), or with --rev the tree
of a commit (git ls-tree -r / git cat-file), so an old commit is measured
without checking it out. Crates: numerics = src/, studies =
crates/persson-studies/src/, cli = crates/persson-cli/src/, python = python/src/.

Every figure is computed on a *masked* copy of each file: comments (//, nested
/* */) blanked, the contents of string literals (incl. raw r#"…"#, byte
strings) and char literals replaced by a non-blank placeholder (a lifetime 'a
is told from a char 'x' by the closing quote). Offsets and lines are kept.

1. Lines: all lines of .rs files under src/; "code" drops lines that are blank
   after masking (blank or comment-only; lines inside a multi-line string
   count as code). Tests: tests/, benches/, examples/, crates/*/tests,
   crates/*/examples (.rs), python/tests (.py, '#' lines as comments).
2. cfg(feature: lines (outside comments) containing cfg(feature, cfg_attr(feature,
   cfg(any(feature, cfg(all(feature or cfg(not(feature. "broad" also counts any
   cfg/cfg_attr/cfg! whose predicate names a feature (e.g. cfg_attr(not(feature..),
   cfg!(not(feature ..), cfg(all(doctest, feature ..)).
3. Production code = src/ minus files named tests.rs, files of a
   `#[cfg(test)] mod x;` and the span of any item attributed #[cfg(test)] or
   #[cfg(all(test ..)] (mod tests { … }, helper fns). A function runs from the
   line of its `fn` to its matching `}` (braces matched on the masked text);
   bodiless trait fns are skipped; nested fns count on their own too; it is
   named Type::fn after its innermost impl/trait block. Listed: functions
   > 120 lines, files with > 800 production lines (files > 800 only with their
   tests are shown, marked so); also functions >= 80 and the median.
4. Import graph: the module tree is followed from lib.rs (else main.rs) through
   `mod x;` (honouring #[path]) and inline `mod x { }`. Paths are the expanded
   trees of every `use` and every inline path `a::b::…` in code whose first
   segment is crate/$crate/super/self, a child module of the current (inline)
   module, a local alias of a module (`use crate::scene;`) or a child of a module
   glob-imported (`use super::*;`). A path resolves to the file of its deepest
   prefix that is a module (re-exports are not followed; inline modules resolve
   to their file). Not edges: a file to itself, `pub use`/`pub(..) use` of a file
   into its own descendants (the re-export pattern), test code. SCCs by Tarjan;
   module level: files collapsed onto their top-level module (below a single
   wrapper module such as cli's `persson_cli`), SCCs and mutual pairs. Also the
   SCCs once every edge from a module into its own descendants is dropped (a
   mod.rs dispatching to children that use its types is a cycle by the rule
   above; this second figure leaves only cycles between siblings/cousins).
   --json lists each edge inside a cycle with the path that made it.
5. Public API: from the crate root, following `pub mod` (file or inline) whose
   declaration sits in a public context. Counted: `pub` (exactly, not pub(..))
   fn/struct/enum/trait/const/static/type/union at module level of a public
   module or inside an impl block there (methods, associated consts/types), and
   `pub mod` (the module count); a `names!` invocation counts as one enum plus
   its `ALL` and `name()`. Not counted: pub use re-exports, fields, variants,
   trait items. "re-exported" counts separately the items of private modules
   that a public module re-exports (`mod x; pub use x::{A, B}` or `x::*`): the
   named items (or all, for *) and the pub methods of impls of those names.
6. Mirror enums: every enum (and names! enum) of studies/cli/python whose set
   of variant names equals, case-insensitively, that of a numerics enum (>= 2
   variants), whatever the names; also `XName` ~ `X` pairs whose variants differ
   (listed with the difference). names! enums: each `names! { … Name { … } }`.
"""
import argparse, bisect, json, os, re, statistics, subprocess, sys
from collections import defaultdict

CRATES = {'numerics': 'src/', 'studies': 'crates/persson-studies/src/',
          'cli': 'crates/persson-cli/src/', 'python': 'python/src/'}
TEST_DIRS = {'numerics': ['tests/', 'benches/', 'examples/'],
             'studies': ['crates/persson-studies/tests/', 'crates/persson-studies/examples/'],
             'cli': ['crates/persson-cli/tests/', 'crates/persson-cli/examples/'],
             'python': ['python/tests/']}
RELEVANT = re.compile(r'^(?:(?:src|tests|benches|examples)/|crates/[^/]+/(?:src|tests|examples)/|python/(?:src|tests)/)')
FN_LIMIT, FN_WARN, FILE_LIMIT = 120, 80, 800
STR = '\x01'

# ---------------------------------------------------------------- reading

def read_tree(root, rev):
    """{path: text} of the relevant .rs/.py files of the working tree or of rev."""
    want = lambda p: RELEVANT.match(p) and (p.endswith('.rs') or p.startswith('python/tests/') and p.endswith('.py'))
    if rev is None:
        paths = []
        for d, dirs, files in os.walk(root):
            dirs[:] = [x for x in dirs if x not in ('target', 'fuzz', '.git', 'node_modules')]
            paths += [os.path.relpath(os.path.join(d, f), root).replace(os.sep, '/') for f in files]
        return {p: open(os.path.join(root, p), encoding='utf-8', errors='replace').read() for p in paths if want(p)}
    names = subprocess.run(['git', '-C', root, 'ls-tree', '-r', '--name-only', '-z', rev],
                           check=True, capture_output=True).stdout.decode().split('\0')
    names = [p for p in names if p and want(p)]
    blob = subprocess.run(['git', '-C', root, 'cat-file', '--batch'], check=True, capture_output=True,
                          input=''.join(f'{rev}:{p}\n' for p in names).encode()).stdout
    out, pos = {}, 0
    for p in names:                                # "<sha> blob <size>\n<content>\n"
        nl = blob.index(b'\n', pos); size = int(blob[pos:nl].split()[2])
        out[p], pos = blob[nl + 1:nl + 1 + size].decode('utf-8', 'replace'), nl + 2 + size
    return out

# ---------------------------------------------------------------- lexing

SPECIAL = re.compile(r'//|/\*|(?<![\w])b?r(#*)"|"|\'')
CHAR = re.compile(r"'(?:\\(?:x[0-9a-fA-F]{2}|u\{[0-9a-fA-F_]*\}|.)|[^\\'\n])'")

def mask(text):
    """Comments -> spaces, literal contents -> STR; newlines and offsets kept."""
    out, i, n = list(text), 0, len(text)
    def blank(a, b, ch):
        out[a:b] = ['\n' if c == '\n' else ch for c in text[a:b]]
    while True:
        m = SPECIAL.search(text, i)
        if not m: return ''.join(out)
        s, tok = m.start(), m.group()
        if tok == '//':
            e = text.find('\n', s); e = n if e < 0 else e
            blank(s, e, ' ')
        elif tok == '/*':
            depth, e = 1, s + 2
            while e < n and depth:
                if text.startswith('/*', e): depth, e = depth + 1, e + 2
                elif text.startswith('*/', e): depth, e = depth - 1, e + 2
                else: e += 1
            blank(s, e, ' ')
        elif tok.endswith('"') and tok != '"':          # raw string
            close = '"' + m.group(1)
            e = text.find(close, m.end()); e = n if e < 0 else e
            blank(m.end(), e, STR); e += len(close)
        elif tok == '"':
            e = s + 1
            while e < n and text[e] != '"':
                e += 2 if text[e] == '\\' else 1
            blank(s + 1, e, STR); e += 1
        else:                                            # char literal or lifetime
            c = CHAR.match(text, s)
            e = c.end() if c else s + 1
            if c: blank(s + 1, e - 1, STR)
        i = e

def strip_attrs(s):
    while True:
        m = re.search(r'#!?\[', s)
        if not m: return s
        d, j = 1, m.end()
        while j < len(s) and d: d += (s[j] == '[') - (s[j] == ']'); j += 1
        s = s[:m.start()] + ' ' + s[j:]

def split_top(s):
    """Split s at the commas outside (), [] and {}."""
    parts, d, cur = [], 0, ''
    for c in s:
        if c == ',' and d == 0: parts.append(cur); cur = ''; continue
        d += (c in '([{') - (c in ')]}'); cur += c
    return [p.strip() for p in parts + [cur] if p.strip()]

def skip_generics(h):
    h, d, j = h.lstrip(), 0, 0
    while j < len(h) and h.startswith('<'):
        d += (h[j] == '<') - (h[j] == '>' and h[j - 1] != '-'); j += 1
        if d == 0: return h[j:]
    return h

class Src:
    """One file: masked text, lines, blocks {open, close, parent, kind, name, pub}, test spans."""
    def __init__(self, path, text):
        self.path, self.text, self.m = path, text, mask(text)
        self.nl = [i for i, c in enumerate(self.m) if c == '\n']
        self.nlines = len(self.nl) + (1 if text and not text.endswith('\n') else 0)
        self.opens, self.blocks, stack = [], [], []
        for mt in re.finditer(r'[{}]', self.m):
            if mt.group() == '{':
                stack.append(len(self.blocks))
                self.opens.append(mt.start())
                self.blocks.append(dict(open=mt.start(), close=len(self.m), parent=stack[-2] if len(stack) > 1 else -1))
            elif stack:
                self.blocks[stack.pop()]['close'] = mt.start()
        for b in self.blocks: self.classify(b)
        self.tests, self.test_mods = [], []   # excluded spans; names of `#[cfg(test)] mod x;`
        for mt in re.finditer(r'#\[cfg\((?:all\()?test\b[^\]]*\]', self.m):
            j = self.item_end(mt.end())
            if j < len(self.m) and self.m[j] == '{':
                self.tests.append((mt.start(), self.blocks[bisect.bisect_left(self.opens, j)]['close']))
            else:
                dm = re.search(r'\bmod\s+(\w+)\s*$', self.m[mt.end():j])
                if dm: self.test_mods.append(dm.group(1))

    def item_end(self, j):
        """Offset of the first '{' or ';' from j outside () and []."""
        d = 0
        while j < len(self.m) and not (d == 0 and self.m[j] in '{;'):
            d += {'(': 1, '[': 1, ')': -1, ']': -1}.get(self.m[j], 0); j += 1
        return j

    def header(self, p):
        return self.m[max(self.m.rfind(c, 0, p) for c in ';{}') + 1:p]

    def classify(self, b):
        h = strip_attrs(self.header(b['open'])).strip()
        b['kind'], b['name'], b['pub'] = 'other', '', False
        if re.search(r'\bfn\s+\w+', h): b['kind'] = 'fn'
        elif (mm := re.fullmatch(r'(pub(?:\([^)]*\))?\s+)?mod\s+(\w+)', h)):
            b.update(kind='mod', name=mm.group(2), pub=(mm.group(1) or '').strip() == 'pub')
        elif re.match(r'(?:unsafe\s+)?impl\b', h):
            rest = skip_generics(re.sub(r'^(?:unsafe\s+)?impl', '', h))
            rest = re.split(r'\bwhere\b', rest)[0]
            t = re.search(r'\bfor\s+&?(?:dyn\s+)?([\w:]+)', rest) or re.match(r'\s*&?(?:dyn\s+)?([\w:]+)', rest)
            b.update(kind='impl', name=t.group(1).split('::')[-1] if t else '?')
        elif (mm := re.match(r'(?:pub(?:\([^)]*\))?\s+)?(?:unsafe\s+)?trait\s+(\w+)', h)):
            b.update(kind='trait', name=mm.group(1))

    def line(self, p): return bisect.bisect_left(self.nl, p) + 1
    def in_test(self, p): return any(a <= p <= b for a, b in self.tests)
    def chain(self, p):
        """Enclosing blocks of offset p, innermost first."""
        i = bisect.bisect_left(self.opens, p) - 1
        while i >= 0 and self.blocks[i]['close'] < p: i = self.blocks[i]['parent']
        out = []
        while i >= 0: out.append(self.blocks[i]); i = self.blocks[i]['parent']
        return out

    def inline_mods(self, p): return [b['name'] for b in reversed(self.chain(p)) if b['kind'] == 'mod']
    def public_ctx(self, p, impl_ok):
        ch = self.chain(p)
        if ch and impl_ok and ch[0]['kind'] == 'impl': ch = ch[1:]
        return all(b['kind'] == 'mod' and b['pub'] for b in ch)
    def test_lines(self): return sum(self.line(b) - self.line(a) + 1 for a, b in self.tests)

# ---------------------------------------------------------------- figures 1-3

CFG = re.compile(r'cfg\(feature|cfg_attr\(feature|cfg\((?:any|all|not)\(feature')
CFG_BROAD = re.compile(r'\bcfg(?:_attr)?!?\s*\(.*\bfeature\s*=')

def line_counts(path, text):
    py = path.endswith('.py')
    ls = text.splitlines() if py else mask(text).splitlines()
    return len(ls), sum(1 for l in ls if l.strip() and not (py and l.lstrip().startswith('#')))

def functions(s):
    """(name, line, length) of every fn with a body outside test spans."""
    out = []
    for mt in re.finditer(r'\bfn\s+(\w+)', s.m):
        if s.in_test(mt.start()): continue
        j = s.item_end(mt.end())
        if j >= len(s.m) or s.m[j] == ';': continue
        close = s.blocks[bisect.bisect_left(s.opens, j)]['close']
        ch = s.chain(mt.start())
        name = f"{ch[0]['name']}::{mt.group(1)}" if ch and ch[0]['kind'] in ('impl', 'trait') else mt.group(1)
        out.append((name, s.line(mt.start()), s.line(close) - s.line(mt.start()) + 1))
    return out

# ---------------------------------------------------------------- module tree, graph

def module_tree(srcs, base):
    """{modpath tuple: file} and per file its modpath, from the crate root via `mod` decls."""
    root = base + ('lib.rs' if base + 'lib.rs' in srcs else 'main.rs')
    mods, files, decls, tests, todo = {(): root}, {root: ()}, [], set(), [root]
    while todo:
        f = todo.pop(); s = srcs.get(f)
        if s is None: continue
        d = os.path.dirname(f)
        here = d if os.path.basename(f) in ('mod.rs', 'lib.rs', 'main.rs') else f[:-3]
        for b in s.blocks:                    # inline modules resolve to their file
            if b['kind'] == 'mod':
                mods.setdefault(files[f] + tuple(s.inline_mods(b['open'] + 1)), f)
        for mt in re.finditer(r'(?<![\w])(pub(?:\([^)]*\))?\s+)?mod\s+(\w+)\s*;', s.m):
            inl, h = s.inline_mods(mt.start()), s.header(mt.start())
            pa = re.search(r'#\[path\s*=\s*"', h)
            if pa:
                h0 = mt.start() - len(h) + pa.end()
                cands = [os.path.normpath(os.path.join(here if inl else d, *inl, s.text[h0:s.text.index('"', h0)]))]
            else:
                cands = ['/'.join([here, *inl, mt.group(2) + '.rs']), '/'.join([here, *inl, mt.group(2), 'mod.rs'])]
            child = next((c for c in cands if c in srcs), None)
            if s.in_test(mt.start()) or mt.group(2) in s.test_mods:
                tests.add(child); continue
            mp = files[f] + tuple(inl) + (mt.group(2),)
            decls.append((f, mt.start(), mp, (mt.group(1) or '').strip() == 'pub', child))
            if child and child not in files:
                mods[mp], files[child] = child, mp; todo.append(child)
    return mods, files, decls, tests

def expand_use(tree):
    """'a::{b, c::d as e, *}' -> [(['a','b'], 'b'), (['a','c','d'], 'e'), (['a','*'], '*')]."""
    tree = re.sub(r'\s+', ' ', tree).strip()
    def go(prefix, s):
        s = s.strip().lstrip(':').strip()
        if '{' in s:
            i = s.index('{'); pre = [x.strip() for x in s[:i].split('::') if x.strip()]
            return [r for part in split_top(s[i + 1:s.rindex('}')]) for r in go(prefix + pre, part)]
        m = re.match(r'(.*?)(?:\s+as\s+(\w+))?$', s)
        segs = prefix + [x.strip() for x in m.group(1).split('::') if x.strip()]
        if segs and segs[-1] == 'self': segs = segs[:-1]
        return [(segs, m.group(2) or (segs[-1] if segs else ''))]
    return go([], tree)

def graph(srcs, base):
    mods, files, _, _ = module_tree(srcs, base)
    children = defaultdict(set)
    for mp in mods:
        if mp: children[mp[:-1]].add(mp[-1])
    edges, why = defaultdict(set), {}
    def add(f, t, path, pos):
        if f != t: edges[f].add(t); why.setdefault((f, t), f'{path} @{srcs[f].line(pos)}')
    for f, modpath in files.items():
        s = srcs[f]
        if os.path.basename(f) == 'tests.rs': continue
        uses = [(mt, expand_use(mt.group(2))) for mt in re.finditer(r'(?<![\w:])(pub(?:\([^)]*\))?\s+)?use\s+([^;]+);', s.m)
                if not s.in_test(mt.start())]
        alias, globs = {}, []
        def absolute(segs, ctx):
            if not segs: return None
            h = segs[0].lstrip('$')
            if h == 'crate': return tuple(segs[1:])
            if h == 'self': return ctx + tuple(segs[1:])
            if h == 'super':
                k = next(i for i, x in enumerate(segs + ['']) if x != 'super')
                return ctx[:len(ctx) - k] + tuple(segs[k:])
            if h in children[ctx]: return ctx + tuple(segs)
            if h in alias: return alias[h] + tuple(segs[1:])
            g = next((g for g in globs if h in children[g]), None)
            return g + tuple(segs) if g is not None else None
        for _ in range(2):                     # aliases may depend on each other
            for mt, items in uses:
                ctx = modpath + tuple(s.inline_mods(mt.start()))
                for segs, name in items:
                    a = absolute(segs[:-1] if name == '*' else segs, ctx)
                    if a is not None and a in mods:
                        if name == '*': globs.append(a) if a not in globs else None
                        else: alias[name] = a
        def target(a):
            while a not in mods: a = a[:-1]
            return mods[a]
        code = list(s.m)
        for mt, items in uses:                 # edges of the use statements, then blank them
            ctx = modpath + tuple(s.inline_mods(mt.start()))
            reexport = mt.group(1) is not None
            for segs, name in items:
                a = absolute([x for x in segs if x != '*'], ctx)
                if a is None or (reexport and len(a) > len(ctx) and a[:len(ctx)] == ctx): continue
                add(f, target(a), '::'.join(segs), mt.start())
            code[mt.start():mt.end()] = ' ' * (mt.end() - mt.start())
        code = ''.join(code)
        for mt in re.finditer(r'(?<![\w:])\$?\w+(?:\s*::\s*\w+)+', code):
            if s.in_test(mt.start()): continue
            a = absolute(re.split(r'\s*::\s*', mt.group().lstrip('$')), modpath + tuple(s.inline_mods(mt.start())))
            if a is not None: add(f, target(a), mt.group(), mt.start())
    return files, edges, why

def tarjan(nodes, edges):
    index, low, stack, on, out, n = {}, {}, [], set(), [], [0]
    def visit(v):
        index[v] = low[v] = n[0]; n[0] += 1; stack.append(v); on.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index: visit(w); low[v] = min(low[v], low[w])
            elif w in on: low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            i = stack.index(v); comp = stack[i:]; del stack[i:]; on.difference_update(comp)
            if len(comp) > 1: out.append(sorted(comp))
    sys.setrecursionlimit(10000)
    for v in sorted(nodes):
        if v not in index: visit(v)
    return out

def cycles(srcs, base):
    files, edges, why = graph(srcs, base)
    file_sccs = [[f[len(base):] for f in c] for c in tarjan(files, edges)]
    mp = dict(files)
    cross = {f: {t for t in ts if mp[t][:len(mp[f])] != mp[f]} for f, ts in edges.items()}
    cross_sccs = [[f[len(base):] for f in c] for c in tarjan(files, cross)]
    strip = 0
    while len({m[strip] for m in mp.values() if len(m) > strip}) == 1: strip += 1   # below a wrapper module
    top = {f: m[strip] for f, m in mp.items() if len(m) > strip}
    medges = defaultdict(set)
    for f, ts in edges.items():
        for t in ts:
            if f in top and t in top and top[f] != top[t]: medges[top[f]].add(top[t])
    mod_sccs = tarjan(set(top.values()), medges)
    mutual = sorted({tuple(sorted((a, b))) for a in medges for b in medges[a] if a in medges.get(b, ())})
    unreached = sorted(p[len(base):] for p in srcs if p.startswith(base) and p not in files and os.path.basename(p) != 'tests.rs')
    inside = [f'{a[len(base):]} -> {b[len(base):]}: {w}' for (a, b), w in sorted(why.items())
              if any(a[len(base):] in c and b[len(base):] in c for c in file_sccs)]
    return dict(files=file_sccs, cross=cross_sccs, modules=mod_sccs, mutual=[f'{a} <-> {b}' for a, b in mutual],
                unreached=unreached, edges=sum(len(v) for v in edges.values()), cycle_edges=inside)

# ---------------------------------------------------------------- public API

ITEM = re.compile(r'(?<![\w(])pub\s+(?:(?:const|async|unsafe|extern(?:\s+"\x01*")?)\s+)*(fn|struct|enum|trait|const|static|type|union|mod)\s+(\w+)')

def public_api(srcs, base):
    mods, files, decls, _ = module_tree(srcs, base)
    by_file = defaultdict(list)
    for f, pos, mp, pub, child in decls: by_file[f].append((pos, pub, child))
    counts = {'strict': defaultdict(int), 'reexported': defaultdict(int)}
    todo, seen = [(mods[()], 'strict', None)], set()
    while todo:
        f, bucket, only = todo.pop()          # only: the names re-exported from f (None: all)
        if (f, bucket) in seen or f not in srcs: continue
        seen.add((f, bucket)); s = srcs[f]
        for mt in ITEM.finditer(s.m):
            kind, ch = mt.group(1), s.chain(mt.start())
            in_impl = bool(ch) and ch[0]['kind'] == 'impl'
            if s.in_test(mt.start()) or not s.public_ctx(mt.start(), kind in ('fn', 'const', 'type')): continue
            if only is not None and (kind == 'mod' or (ch[0]['name'] if in_impl else mt.group(2)) not in only): continue
            counts[bucket]['method' if in_impl and kind == 'fn' else kind] += 1
        for mt in re.finditer(r'\bnames!\s*\{', s.m):
            name = re.match(r'\s*(\w+)', strip_attrs(s.m[mt.end():mt.end() + 2000])).group(1)
            if s.public_ctx(mt.start(), False) and (only is None or name in only):
                counts[bucket]['enum'] += 1; counts[bucket]['method'] += 1; counts[bucket]['const'] += 1
        reexp = defaultdict(set)              # private child -> names this file re-exports from it
        for m in re.finditer(r'(?<![\w(])pub\s+use\s+([^;]+);', s.m):
            if s.public_ctx(m.start(), False):
                for segs, _ in expand_use(m.group(1)):
                    segs = segs[1:] if segs[:1] == ['self'] else segs
                    if len(segs) >= 2: reexp[segs[0]].add(segs[-1])
        for pos, pub, child in by_file[f]:
            if not child or not s.public_ctx(pos, False): continue
            if pub and only is None: todo.append((child, bucket, None))
            elif not pub and (names := reexp.get(files[child][-1])):
                names = only if '*' in names else names if only is None else names & only
                if names is None or names: todo.append((child, 'reexported', names))
    res = {}
    for b, c in counts.items():
        res[b] = dict(c, items=sum(v for k, v in c.items() if k != 'mod'), modules=c.get('mod', 0))
    return res

# ---------------------------------------------------------------- enums

def enums(s):
    """[(name, [variants], line)] of `enum` items and names! invocations (outside tests)."""
    def body_variants(body, names_macro):
        ms = [re.match(r'(\w+)\s*' + ('=' if names_macro else ''), p) for p in split_top(strip_attrs(body))]
        return [m.group(1) for m in ms if m]
    out = []
    for mt in re.finditer(r'\benum\s+(\w+)[^{;]*\{', s.m):
        if s.in_test(mt.start()): continue
        b = s.blocks[bisect.bisect_left(s.opens, mt.end() - 1)]
        out.append((mt.group(1), body_variants(s.m[mt.end():b['close']], False), s.line(mt.start()), False))
    for mt in re.finditer(r'\bnames!\s*\{', s.m):
        b = s.blocks[bisect.bisect_left(s.opens, mt.end() - 1)]
        inner = strip_attrs(s.m[mt.end():b['close']])
        if (em := re.match(r'\s*(\w+)\s*\{', inner)):
            out.append((em.group(1), body_variants(inner[em.end():inner.rindex('}')], True), s.line(mt.start()), True))
    return out

def mirrors(srcs):
    num = [(n, v, p, l) for p, s in srcs.items() if p.startswith(CRATES['numerics']) for n, v, l, _ in enums(s)]
    pairs, names_enums = [], []
    for crate in ('studies', 'cli', 'python'):
        for p, s in sorted(srcs.items()):
            if not p.startswith(CRATES[crate]): continue
            for n, v, l, macro in enums(s):
                loc = f'{crate}:{p[len(CRATES[crate]):]}:{l}'
                if macro: names_enums.append(f'{n} ({len(v)}) {loc}')
                vs = {x.lower() for x in v}
                for nn, nv, np, nl in num:
                    same_set = len(vs) >= 2 and vs == {x.lower() for x in nv}
                    same_name = n == nn + 'Name'
                    if same_set or same_name:
                        pairs.append(dict(enum=n, at=loc, mirrors=nn, of=f'{np[len("src/"):]}:{nl}',
                                          variants='equal' if same_set else
                                          f'differ (+{sorted(vs - {x.lower() for x in nv})} -{sorted({x.lower() for x in nv} - vs)})'))
    return pairs, names_enums

# ---------------------------------------------------------------- report

def measure(root, rev):
    texts = read_tree(root, rev)
    srcs = {p: Src(p, t) for p, t in texts.items() if p.endswith('.rs') and any(p.startswith(b) for b in CRATES.values())}
    out = {'rev': rev or 'working tree', 'crates': {}}
    for crate, base in CRATES.items():
        mine = {p: s for p, s in srcs.items() if p.startswith(base)}
        tot = [line_counts(p, texts[p]) for p in mine]
        tests = [line_counts(p, t) for p, t in texts.items() if any(p.startswith(d) for d in TEST_DIRS[crate])]
        cfg = [l for s in mine.values() for l in s.m.splitlines() if 'feature' in l]
        _, _, _, test_files = module_tree(srcs, base)
        test_files |= {p for p in mine if os.path.basename(p) == 'tests.rs'}
        fns, big_files = [], []
        for p, s in sorted(mine.items()):
            if p in test_files: continue
            fns += [(p[len(base):], *f) for f in functions(s)]
            prod = s.nlines - s.test_lines()
            if prod > FILE_LIMIT or s.nlines > FILE_LIMIT:
                big_files.append(dict(path=p[len(base):], lines=prod, total=s.nlines, over=prod > FILE_LIMIT))
        lens = [f[3] for f in fns]
        out['crates'][crate] = dict(
            lines=dict(total=sum(t for t, _ in tot), code=sum(c for _, c in tot), files=len(tot)),
            tests=dict(total=sum(t for t, _ in tests), code=sum(c for _, c in tests), files=len(tests)),
            cfg_feature=dict(strict=sum(1 for l in cfg if CFG.search(l)), broad=sum(1 for l in cfg if CFG_BROAD.search(l))),
            functions=dict(count=len(lens), median=round(statistics.median(lens), 1) if lens else 0,
                           ge80=sum(1 for x in lens if x >= FN_WARN),
                           over120=[dict(at=f'{p}:{l}', name=n, lines=x) for p, n, l, x in sorted(fns, key=lambda f: -f[3]) if x > FN_LIMIT]),
            big_files=sorted(big_files, key=lambda b: -b['total']),
            cycles=cycles(srcs, base))
        if crate in ('numerics', 'studies'):
            out['crates'][crate]['public_api'] = public_api(srcs, base)
    out['mirror_enums'], out['names_enums'] = mirrors(srcs)
    return out

def text_report(r):
    L = [f"persson structure — {r['rev']}"]
    for crate, c in r['crates'].items():
        f = c['functions']
        L.append(f"\n[{crate}] {CRATES[crate]}")
        L.append(f"  lines {c['lines']['total']} ({c['lines']['code']} code) in {c['lines']['files']} files; "
                 f"tests/benches/examples {c['tests']['total']} ({c['tests']['code']} code) in {c['tests']['files']} files")
        L.append(f"  cfg(feature lines {c['cfg_feature']['strict']} (broad {c['cfg_feature']['broad']})")
        L.append(f"  functions {f['count']}, median {f['median']:g} lines, >= {FN_WARN}: {f['ge80']}, > {FN_LIMIT}: {len(f['over120'])}")
        L += [f"    {o['lines']:5}  {o['name']}  {o['at']}" for o in f['over120']]
        L += [f"  file {b['path']} {b['lines']} lines" + (f" ({b['total']} with tests)" if b['total'] != b['lines'] else '')
              + ('' if b['over'] else f'  [> {FILE_LIMIT} only with tests]') for b in c['big_files']]
        cy = c['cycles']
        L.append(f"  import graph: {cy['edges']} file edges, {len(cy['files'])} file cycle(s)")
        L += [f"    cycle of {len(s)}: {' '.join(s)}" for s in cy['files']]
        L += [f"    module cycle: {' '.join(s)}" for s in cy['modules']]
        if cy['mutual']: L.append(f"    mutual: {', '.join(cy['mutual'])}")
        L.append(f"  without parent->own-submodule edges: {len(cy['cross'])} file cycle(s)")
        L += [f"    cycle of {len(s)}: {' '.join(s)}" for s in cy['cross']]
        if cy['unreached']: L.append(f"    not reached by mod declarations: {' '.join(cy['unreached'])}")
        if 'public_api' in c:
            a = c['public_api']
            kinds = ' '.join(f"{k} {v}" for k, v in sorted(a['strict'].items()) if k not in ('items', 'modules', 'mod'))
            L.append(f"  public API: {a['strict']['items']} items in {a['strict']['modules']} pub modules ({kinds});"
                     f" + {a['reexported']['items']} items of private modules re-exported by pub use")
    L.append(f"\nmirror enums ({sum(1 for p in r['mirror_enums'] if p['variants'] == 'equal')} with equal variants):")
    L += [f"  {p['enum']} ({p['at']}) ~ {p['mirrors']} (src/{p['of']}): {p['variants']}" for p in r['mirror_enums']]
    L.append(f"names! enums ({len(r['names_enums'])}): " + '; '.join(r['names_enums']))
    return '\n'.join(L)

if __name__ == '__main__':
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--rev'); ap.add_argument('--json', action='store_true')
    a = ap.parse_args()
    root = subprocess.run(['git', 'rev-parse', '--show-toplevel'], capture_output=True, text=True,
                          cwd=os.path.dirname(os.path.abspath(__file__))).stdout.strip() or '.'
    r = measure(root, a.rev)
    print(json.dumps(r, indent=1, ensure_ascii=False) if a.json else text_report(r))
