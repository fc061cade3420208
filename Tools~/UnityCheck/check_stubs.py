#!/usr/bin/env python3
"""check_stubs.py - verify hand-written C# declaration stubs against real C# sources.

This is the project's copy of ../shared/tools/unity-api/check_stubs.py (read-only there), extended with
one rule: a type's [AttributeUsage(...)] must be the same in stub and source (present in both with the
same arguments, or absent in both), so that the C# compiler rejects a misplaced attribute as Unity's
compiler would (CS0592). Search "AttributeUsage" below for the extension.

Usage:
    check_stubs.py [-v] [--no-hints] STUB_DIR ROOT [ROOT ...]

    ROOT        a source tree, given as PATH or NAME=PATH (NAME defaults to the
                directory's basename), e.g.
                  unity=SRC/UnityCsReference inference=SRC/com.unity.ai.inference

Every type member declared in STUB_DIR/**/*.cs (methods, constructors, operators,
properties, indexers, fields, events, enum members) must cite where it is declared:

    // source: REL                 REL is relative to a ROOT; tried in every root where it exists
    // source: NAME:REL            REL in the root called NAME only
    // source: Some/Dir/**/Foo*.cs glob wildcards (*, ?, **) search every matching file
                                   (use this for partial types spread over several files)

The comment may sit on any line of the declaration (trailing comment) or on the
comment-only lines directly above it; a citation on/above a type declaration applies
to all members of that type (and nested types) that have none of their own.

A stub member matches a source declaration when the declaring type (namespace, name,
generic arity, nesting) is the same, and the member has the same kind, name, generic
arity, parameter count and parameter types (namespaces stripped, ref/in/out/params/this
are part of the type, built-in aliases unified), the same return/property/field type,
the same static-ness, a compatible accessibility (public/protected/non-public), and:
optional stub parameters must be optional in the source, stub property accessors must
exist (and be accessible) in the source, generic constraints must be equal, explicit
enum values must agree. Types are checked too (kind, static-ness, accessibility, listed
base types).

Output: one line per mismatch
    STUB_FILE:LINE: member X: not found in SOURCE_FILE (closest: ...)
and a final line "N members checked, M mismatches". Exit status 1 on any mismatch,
2 on usage errors. Standard library only.
"""
import argparse
import bisect
import difflib
import glob
import os
import re
import sys

# --------------------------------------------------------------------------------------
# Lexing: blank out comments, string/char literals and preprocessor lines while keeping
# every character position (and so every line number) unchanged.
# --------------------------------------------------------------------------------------


def _blank(out, a, b):
    for k in range(a, b):
        if out[k] != '\n':
            out[k] = ' '


def _is_string_start(src, i):
    n = len(src)
    j = i
    while j < n and src[j] in '$@':
        j += 1
    return j < n and src[j] == '"' and (j == i or src[i] in '$@')


def _scan_char(src, i):
    n = len(src)
    j = i + 1
    if j < n and src[j] == '\\':
        j += 2
    else:
        j += 1
    while j < n and src[j] != "'" and src[j] != '\n':
        j += 1
    return min(n, j + 1)


def _scan_string(src, i):
    """src[i] starts a string literal (possibly with $ / @ prefixes); return end index."""
    n = len(src)
    j = i
    dollars = 0
    verbatim = False
    while j < n and src[j] in '$@':
        if src[j] == '$':
            dollars += 1
        else:
            verbatim = True
        j += 1
    if src.startswith('"""', j):  # raw string literal
        q = 0
        while j < n and src[j] == '"':
            q += 1
            j += 1
        k = src.find('"' * q, j)
        return n if k < 0 else k + q
    j += 1
    while j < n:
        ch = src[j]
        if verbatim:
            if ch == '"':
                if j + 1 < n and src[j + 1] == '"':
                    j += 2
                    continue
                return j + 1
        else:
            if ch == '\\':
                j += 2
                continue
            if ch == '"':
                return j + 1
            if ch == '\n':
                return j
        if dollars and ch == '{':
            if j + 1 < n and src[j + 1] == '{':
                j += 2
                continue
            j = _skip_interp(src, j + 1)
            continue
        j += 1
    return n


def _skip_interp(src, j):
    n = len(src)
    depth = 0
    while j < n:
        ch = src[j]
        if ch == '"' or (ch in '$@' and _is_string_start(src, j)):
            j = _scan_string(src, j)
            continue
        if ch == "'":
            j = _scan_char(src, j)
            continue
        if ch == '/' and j + 1 < n and src[j + 1] == '*':
            k = src.find('*/', j + 2)
            j = n if k < 0 else k + 2
            continue
        if ch == '{':
            depth += 1
        elif ch == '}':
            if depth == 0:
                return j + 1
            depth -= 1
        j += 1
    return n


def clean_source(src):
    out = list(src)
    n = len(src)
    i = 0
    line_blank = True  # only whitespace since the last newline
    while i < n:
        c = src[i]
        if c == '\n':
            line_blank = True
            i += 1
            continue
        if c in ' \t\r\f\v\ufeff':
            i += 1
            continue
        if c == '#' and line_blank:
            j = src.find('\n', i)
            j = n if j < 0 else j
            _blank(out, i, j)
            i = j
            continue
        line_blank = False
        if c == '/' and i + 1 < n and src[i + 1] == '/':
            j = src.find('\n', i)
            j = n if j < 0 else j
            _blank(out, i, j)
            i = j
            continue
        if c == '/' and i + 1 < n and src[i + 1] == '*':
            j = src.find('*/', i + 2)
            j = n if j < 0 else j + 2
            _blank(out, i, j)
            i = j
            continue
        if c == '"' or (c in '$@' and _is_string_start(src, i)):
            j = _scan_string(src, i)
            _blank(out, i, j)
            out[i] = '"'
            if j - 1 > i and out[j - 1] != '\n':
                out[j - 1] = '"'
            i = j
            continue
        if c == "'":
            j = _scan_char(src, i)
            _blank(out, i, j)
            out[i] = "'"
            if j - 1 > i and out[j - 1] != '\n':
                out[j - 1] = "'"
            i = j
            continue
        i += 1
    return ''.join(out)


# --------------------------------------------------------------------------------------
# Small scanning helpers over cleaned text
# --------------------------------------------------------------------------------------

IDENT = re.compile(r'@?[A-Za-z_][A-Za-z0-9_]*')
WS = re.compile(r'\s*')


def skip_ws(s, i):
    return WS.match(s, i).end()


def match_pair(s, i, op, cl):
    """s[i] == op; return index of the matching cl (counting all bracket kinds), or -1."""
    depth = 0
    n = len(s)
    j = i
    while j < n:
        ch = s[j]
        if ch in '([{':
            depth += 1
        elif ch in ')]}':
            depth -= 1
            if depth == 0:
                return j if ch == cl else -1
        j += 1
    return -1


def match_angle(s, i):
    """s[i] == '<'; return index of the matching '>' of a generic argument list, or -1."""
    depth = 0
    n = len(s)
    j = i
    while j < n:
        ch = s[j]
        if ch == '<':
            depth += 1
        elif ch == '>':
            depth -= 1
            if depth == 0:
                return j
        elif ch in '([':
            k = match_pair(s, j, ch, ')' if ch == '(' else ']')
            if k < 0:
                return -1
            j = k
        elif ch in ';{}=)]':
            return -1
        j += 1
    return -1


def split_top(s, sep=','):
    """Split on sep at bracket depth 0 (() [] {} <> counted only when balanced-looking)."""
    parts = []
    depth = 0
    cur = 0
    i = 0
    n = len(s)
    while i < n:
        ch = s[i]
        if ch in '([{':
            depth += 1
        elif ch in ')]}':
            depth -= 1
        elif ch == '<':
            k = match_angle(s, i)
            if k > 0:
                i = k
        elif ch == sep and depth == 0:
            parts.append(s[cur:i])
            cur = i + 1
        i += 1
    parts.append(s[cur:])
    return parts


def skip_attributes(s, i):
    """Skip [..] attribute sections starting at i; return (new_index, attribute_text)."""
    texts = []
    while True:
        i = skip_ws(s, i)
        if i < len(s) and s[i] == '[':
            j = match_pair(s, i, '[', ']')
            if j < 0:
                return i, ''.join(texts)
            texts.append(s[i:j + 1])
            i = j + 1
        else:
            return i, ''.join(texts)


_USAGE_RE = re.compile(r'\bAttributeUsage(?:Attribute)?\s*\(')


def attribute_usage(attr_text):
    """The arguments of an [AttributeUsage(...)] among a declaration's attribute sections, normalised
    (whitespace and `System.` removed), or None when there is none."""
    m = _USAGE_RE.search(attr_text)
    if not m:
        return None
    j = match_pair(attr_text, m.end() - 1, '(', ')')
    if j < 0:
        return None
    args = re.sub(r'\s+', '', attr_text[m.end():j]).replace('System.', '')
    return ','.join(sorted(split_top(args)))


def read_type(s, i):
    """Read a type expression at s[i:]; return (text, end) or None."""
    n = len(s)
    i = skip_ws(s, i)
    start = i
    if i < n and s[i] == '(':  # tuple type
        j = match_pair(s, i, '(', ')')
        if j < 0:
            return None
        i = j + 1
    else:
        m = IDENT.match(s, i)
        if not m:
            return None
        i = m.end()
        while True:
            k = skip_ws(s, i)
            if s.startswith('::', k):
                m = IDENT.match(s, skip_ws(s, k + 2))
                if not m:
                    break
                i = m.end()
                continue
            if k < n and s[k] == '<':
                j = match_angle(s, k)
                if j < 0:
                    break
                i = j + 1
                continue
            if k < n and s[k] == '.':
                m = IDENT.match(s, skip_ws(s, k + 1))
                if not m:
                    break
                i = m.end()
                continue
            break
    while True:
        k = skip_ws(s, i)
        if k < n and s[k] in '?*':
            i = k + 1
            continue
        if k < n and s[k] == '[':
            j = k + 1
            while j < n and s[j] in ' \t\r\n,':
                j += 1
            if j < n and s[j] == ']':
                i = j + 1
                continue
        break
    return s[start:i], i


# --------------------------------------------------------------------------------------
# Type-name normalisation
# --------------------------------------------------------------------------------------

ALIASES = {
    'Int32': 'int', 'UInt32': 'uint', 'Int16': 'short', 'UInt16': 'ushort',
    'Int64': 'long', 'UInt64': 'ulong', 'Byte': 'byte', 'SByte': 'sbyte',
    'Single': 'float', 'Double': 'double', 'Boolean': 'bool', 'Char': 'char',
    'String': 'string', 'Decimal': 'decimal', 'Void': 'void',
}
_ALIAS_RE = re.compile(r'(?<![\w.])(' + '|'.join(ALIASES) + r')\b(?!\s*\.)')
_QUAL_RE = re.compile(r'(?<![\w>\]@])@?[A-Za-z_]\w*\s*(?:\.|::)\s*(?=@?[A-Za-z_])')
_PUNCT_RE = re.compile(r'\s*([<>\[\](),?*.])\s*')


def norm_type(t, tmap=None):
    s = ' '.join(t.split())
    s = re.sub(r'\bglobal\s*::\s*', '', s)
    s = re.sub(r'\bSystem\s*\.\s*Object\b', 'object', s)
    s = _QUAL_RE.sub('', s)
    s = s.replace('@', '')
    s = _PUNCT_RE.sub(r'\1', s)
    s = _ALIAS_RE.sub(lambda m: ALIASES[m.group(1)], s)
    prev = None
    while prev != s:
        prev = s
        s = re.sub(r'\bNullable<([^<>]+)>', r'\1?', s)
    if tmap:
        s = re.sub(r'(?<![\w.`])([A-Za-z_]\w*)\b', lambda m: tmap.get(m.group(1), m.group(1)), s)
    return s


def type_params(text):
    """'<in T, [X] U>' -> ['T', 'U']"""
    if not text:
        return []
    inner = text.strip()[1:-1]
    names = []
    for p in split_top(inner):
        p = re.sub(r'\[[^\]]*\]', ' ', p)
        p = re.sub(r'^\s*(in|out)\s+', '', p)
        m = IDENT.search(p)
        names.append(m.group(0).lstrip('@') if m else '?')
    return names


def parse_constraints(text, tmap):
    res = {}
    for part in re.split(r'\bwhere\b', text)[1:]:
        if ':' not in part:
            continue
        name, cons = part.split(':', 1)
        name = name.strip().lstrip('@')
        items = [norm_type(c, tmap) for c in split_top(cons) if c.strip()]
        res[tmap.get(name, name)] = tuple(items)
    return res


# --------------------------------------------------------------------------------------
# Declarations
# --------------------------------------------------------------------------------------

MEMBER_MODS = ('public', 'private', 'protected', 'internal', 'static', 'extern', 'unsafe',
               'readonly', 'virtual', 'override', 'abstract', 'sealed', 'new', 'partial',
               'const', 'volatile', 'async', 'required', 'event', 'delegate', 'implicit',
               'explicit', 'fixed', 'file')
_MOD_RE = re.compile(r'\s*(' + '|'.join(MEMBER_MODS) + r')\b(?!\s*[.(<:])')
TYPE_MODS = r'(?:(?:public|private|protected|internal|static|sealed|abstract|partial|unsafe|readonly|ref|new|file)\s+)*'
_TYPE_RE = re.compile(r'(?P<mods>' + TYPE_MODS + r')(?P<kind>class|struct|interface|enum|record\s+struct|record\s+class|record)\s+@?(?P<name>[A-Za-z_]\w*)')
_NS_RE = re.compile(r'namespace\s+(?P<name>[\w.@]+)\s*$')

KIND_CAT = {'method': 'method', 'ctor': 'method', 'operator': 'method', 'conversion': 'method',
            'property': 'property', 'indexer': 'property', 'field': 'field', 'event': 'event',
            'enum': 'enum'}


def access_of(mods, default):
    has = [m for m in ('public', 'protected', 'internal', 'private') if m in mods]
    if not has:
        return default
    return ' '.join(has)


def access_group(acc):
    if acc == 'public':
        return 'public'
    if acc in ('protected', 'protected internal', 'internal protected'):
        return 'protected'
    return 'non-public'


class TypeDecl:
    def __init__(self):
        self.ns = ''
        self.name = ''
        self.kind = ''
        self.mods = set()
        self.access = ''
        self.tparams = []
        self.all_tparams = []
        self.constraints = {}
        self.bases = []
        self.outer = None
        self.file = ''
        self.line = 0
        self.span = (0, 0)
        self.sig = None  # for delegates: Member
        self.usage = None  # [AttributeUsage(...)] arguments, whitespace removed; None when absent

    @property
    def path(self):
        p = []
        t = self
        while t:
            p.append((t.name, len(t.tparams)))
            t = t.outer
        return tuple(reversed(p))

    @property
    def key(self):
        return (self.ns, self.path)

    def display(self):
        parts = []
        t = self
        while t:
            parts.append(t.name + ('<' + ','.join(t.tparams) + '>' if t.tparams else ''))
            t = t.outer
        return '.'.join(reversed(parts))

    def tmap(self):
        return {n: '`%d' % k for k, n in enumerate(self.all_tparams)}

    @property
    def static(self):
        return 'static' in self.mods


class Member:
    def __init__(self):
        self.kind = ''
        self.name = ''
        self.ret = ''          # normalised
        self.ret_raw = ''
        self.params = []       # list of (normtype, optional, rawtext)
        self.garity = 0
        self.constraints = {}
        self.static = False
        self.access = ''
        self.accessors = None  # dict name->access for properties/indexers/events
        self.value = None      # enum value (int) if known
        self.value_given = False
        self.owner = None      # TypeDecl
        self.file = ''
        self.line = 0
        self.span = (0, 0)     # first/last line of the declaration header

    def sig_key(self):
        return (KIND_CAT[self.kind], self.name, self.garity, tuple(p[0] for p in self.params))

    def pretty(self, text):
        """replace generic-parameter placeholders (`0 = type's, ``0 = method's) by their names"""
        rev = getattr(self, 'rev', None) or {}
        return re.sub(r'``?\d+', lambda m: rev.get(m.group(0), m.group(0)), text)

    def display(self, with_type=True):
        owner = self.owner.display() + '.' if (with_type and self.owner) else ''
        g = '<' + ','.join(self.pretty('``%d' % k) for k in range(self.garity)) + '>' if self.garity else ''
        if self.kind in ('method', 'operator', 'conversion', 'ctor', 'delegate'):
            s = '%s%s%s(%s)' % (owner, self.name, g, ', '.join(p[0] for p in self.params))
        elif self.kind == 'indexer':
            s = '%sthis[%s]' % (owner, ', '.join(p[0] for p in self.params))
        else:
            s = owner + self.name
        return self.pretty(s)

    def signature(self):
        bits = [self.access]
        if self.static:
            bits.append('static')
        if self.kind not in ('ctor', 'enum'):
            bits.append(self.ret)
        s = self.pretty(' '.join(b for b in bits if b)) + ' ' + self.display(with_type=False)
        if self.kind in ('property', 'indexer', 'event') and self.accessors is not None:
            s += ' {' + ' '.join(sorted(self.accessors)) + '}'
        if self.kind == 'enum' and self.value is not None:
            s += ' = %d' % self.value
        return s


class SourceFile:
    """Parses one C# file into TypeDecls and Members."""

    def __init__(self, path, display=None, text=None, is_stub=False):
        self.is_stub = is_stub  # stubs expand multi-field declarators at check time (own line/citation)
        self.path = path
        self.display = display or path
        if text is None:
            with open(path, encoding='utf-8-sig', errors='replace') as f:
                text = f.read()
        self.raw = text
        self.t = clean_source(text)
        self.line_starts = [0] + [m.end() for m in re.finditer('\n', self.t)]
        self.types = []
        self.members = []
        self.by_type = {}
        self.errors = []
        n = len(self.t)
        pos = 0
        while pos < n:
            pos = self.scan_scope(pos, '', None)

    # -- positions --------------------------------------------------------------------
    def line_of(self, pos):
        return bisect.bisect_right(self.line_starts, pos)

    def first_code(self, a, b):
        """position of the first non-space char of t[a:b] after attributes"""
        i, _ = skip_attributes(self.t, a)
        return min(i, b)

    # -- scopes -----------------------------------------------------------------------
    def match_brace(self, i):
        j = match_pair(self.t, i, '{', '}')
        if j < 0:
            # fall back: plain brace counting
            depth = 0
            for k in range(i, len(self.t)):
                if self.t[k] == '{':
                    depth += 1
                elif self.t[k] == '}':
                    depth -= 1
                    if depth == 0:
                        return k
            return len(self.t) - 1
        return j

    def scan_to_semicolon(self, i):
        t = self.t
        n = len(t)
        depth = 0
        while i < n:
            ch = t[i]
            if ch in '([{':
                depth += 1
            elif ch in ')]}':
                if depth == 0:
                    return i - 1  # ran into the scope's closing brace
                depth -= 1
            elif ch == ';' and depth == 0:
                return i
            i += 1
        return n - 1

    def scan_scope(self, i, ns, outer):
        t = self.t
        n = len(t)
        hs = i
        depth = 0
        while i < n:
            c = t[i]
            if c in '([':
                depth += 1
            elif c in ')]':
                depth = max(0, depth - 1)
            elif depth == 0:
                if c == ';':
                    hdr = t[hs:i]
                    m = _NS_RE.match(hdr.strip())
                    if m and outer is None:
                        ns = (ns + '.' if ns else '') + m.group('name')
                    else:
                        self.header(hs, i, ';', ns, outer)
                    i += 1
                    hs = i
                    continue
                if c == '{':
                    hdr = t[hs:i]
                    a = self.first_code(hs, i)
                    core = t[a:i]
                    m = _NS_RE.match(core.strip())
                    if m:
                        i = self.scan_scope(i + 1, (ns + '.' if ns else '') + m.group('name'), None)
                        hs = i
                        continue
                    m = _TYPE_RE.match(core)
                    if m:
                        td = self.make_type(hs, a, i, m, ns, outer)
                        end = self.match_brace(i)
                        td.span = (td.span[0], self.line_of(i))
                        if td.kind == 'enum':
                            self.enum_members(td, i + 1, end)
                            i = end + 1
                        else:
                            i = self.scan_scope(i + 1, ns, td)
                        hs = i
                        continue
                    end = self.match_brace(i)
                    self.header(hs, i, '{', ns, outer, body=(i + 1, end))
                    i = end + 1
                    hs = i
                    continue
                if c == '}':
                    return i + 1
                if c == '=':
                    nxt = t[i + 1] if i + 1 < n else ''
                    prv = t[i - 1] if i > 0 else ''
                    if nxt == '>':
                        end = self.scan_to_semicolon(i + 2)
                        self.header(hs, i, '=>', ns, outer)
                        i = end + 1
                        hs = i
                        continue
                    if nxt != '=' and prv not in '=!<>':
                        end = self.scan_to_semicolon(i + 1)
                        self.header(hs, end + 1, 'init', ns, outer)
                        i = end + 1
                        hs = i
                        continue
            i += 1
        return n

    # -- types ------------------------------------------------------------------------
    def make_type(self, hs, a, brace, m, ns, outer):
        t = self.t
        td = TypeDecl()
        td.ns = ns
        td.outer = outer
        td.file = self.display
        td.kind = ' '.join(m.group('kind').split())
        td.name = m.group('name')
        td.mods = set(m.group('mods').split())
        default = 'public' if outer is not None and outer.kind in ('interface',) else (
            'private' if outer is not None else 'internal')
        td.access = access_of(td.mods, default)
        td.line = self.line_of(a)
        td.span = (self.line_of(skip_ws(t, hs)), self.line_of(brace))
        td.usage = attribute_usage(t[hs:a])
        rest = t[a + m.end():brace]
        j = skip_ws(rest, 0)
        if j < len(rest) and rest[j] == '<':
            k = match_angle(rest, j)
            if k > 0:
                td.tparams = type_params(rest[j:k + 1])
                j = k + 1
        td.all_tparams = (outer.all_tparams if outer else []) + td.tparams
        j = skip_ws(rest, j)
        if j < len(rest) and rest[j] == '(':  # primary constructor
            k = match_pair(rest, j, '(', ')')
            j = k + 1 if k > 0 else j
        rest = rest[j:]
        wpos = re.search(r'\bwhere\b', rest)
        basepart = rest[:wpos.start()] if wpos else rest
        tmap = td.tmap()
        if wpos:
            td.constraints = parse_constraints(rest[wpos.start():], tmap)
        basepart = basepart.strip()
        if basepart.startswith(':'):
            td.bases = [norm_type(b, tmap) for b in split_top(basepart[1:]) if b.strip()]
        self.add_type(td)
        return td

    def add_type(self, td):
        self.types.append(td)
        self.by_type.setdefault(td.key, [])

    def enum_members(self, td, a, b):
        body = self.t[a:b]
        pos = 0
        prev_val = -1
        known = {}
        for part in split_top(body):
            start = pos
            pos += len(part) + 1
            i, _ = skip_attributes(part, 0)
            m = IDENT.match(part, i)
            if not m:
                continue
            mem = Member()
            mem.kind = 'enum'
            mem.name = m.group(0).lstrip('@')
            mem.owner = td
            mem.static = True
            mem.access = 'public'
            mem.file = self.display
            mem.line = self.line_of(a + start + m.start())
            mem.span = (self.line_of(a + start + skip_ws(part, 0)), self.line_of(a + start + len(part)))
            mem.ret = norm_type(td.display())
            rest = part[m.end():].strip()
            val = None
            if rest.startswith('='):
                mem.value_given = True
                val = eval_enum_value(rest[1:], known)
            elif prev_val is not None:
                val = prev_val + 1
            mem.value = val
            prev_val = val
            known[mem.name] = val
            self.add_member(mem)

    def add_member(self, mem):
        self.members.append(mem)
        self.by_type.setdefault(mem.owner.key, []).append(mem)

    # -- members ----------------------------------------------------------------------
    def header(self, hs, end, term, ns, outer, body=None):
        t = self.t
        s = t[hs:end]
        if not s.strip():
            return
        i, attrs = skip_attributes(s, 0)
        mods = []
        while True:
            m = _MOD_RE.match(s, i)
            if not m:
                break
            mods.append(m.group(1))
            i = m.end()
        if outer is None and 'delegate' not in mods:
            return
        if outer is not None and outer.kind == 'enum':
            return
        try:
            mem = self.parse_member(s, i, mods, term, outer)
        except Exception as e:  # pragma: no cover - defensive
            self.errors.append('%s:%d: parse error: %s' % (self.display, self.line_of(hs), e))
            return
        if mem is None:
            return
        a = hs + skip_ws(s, 0)
        mem.file = self.display
        mem.line = self.line_of(hs + skip_attributes(s, 0)[0])
        mem.span = (self.line_of(a), self.line_of(max(hs, end)))
        if mem.kind == 'delegate':
            td = TypeDecl()
            td.ns = ns
            td.outer = outer
            td.file = self.display
            td.kind = 'delegate'
            td.name = mem.name
            td.mods = set(mods)
            td.access = access_of(td.mods, 'private' if outer else 'internal')
            td.tparams = mem._tparams
            td.all_tparams = (outer.all_tparams if outer else []) + td.tparams
            td.line = mem.line
            td.span = mem.span
            td.sig = mem
            mem.owner = td
            self.add_type(td)
            return
        if mem.kind in ('property', 'indexer', 'event'):
            if term == '=>':
                mem.accessors = {'get': mem.access}
            elif body is not None:
                mem.accessors = self.parse_accessors(body, mem.access)
            else:
                mem.accessors = {'add': mem.access, 'remove': mem.access} if mem.kind == 'event' else {}
        self.add_member(mem)
        if outer is not None and getattr(mem, '_extra', None) and not self.is_stub:
            for nm in mem._extra:  # "public float x, y, z;" declares three fields
                clone = Member()
                clone.__dict__.update(mem.__dict__)
                clone.name = nm
                clone._extra = []
                self.add_member(clone)

    def parse_accessors(self, body, acc):
        s = self.t[body[0]:body[1]]
        res = {}
        i = 0
        n = len(s)
        while i < n:
            i, _ = skip_attributes(s, i)
            mods = []
            while True:
                m = re.compile(r'\s*(public|private|protected|internal|readonly)\b').match(s, i)
                if not m:
                    break
                mods.append(m.group(1))
                i = m.end()
            m = re.compile(r'\s*(get|set|init|add|remove)\b').match(s, i)
            if not m:
                break
            name = m.group(1)
            res[name] = access_of([x for x in mods if x != 'readonly'], acc)
            i = skip_ws(s, m.end())
            if i < n and s[i] == ';':
                i += 1
            elif i < n and s[i] == '{':
                j = match_pair(s, i, '{', '}')
                i = n if j < 0 else j + 1
            elif s.startswith('=>', i):
                depth = 0
                while i < n:
                    if s[i] in '([{':
                        depth += 1
                    elif s[i] in ')]}':
                        depth -= 1
                    elif s[i] == ';' and depth == 0:
                        break
                    i += 1
                i += 1
            else:
                break
        return res

    def parse_member(self, s, i, mods, term, outer):
        n = len(s)
        mem = Member()
        mem.owner = outer
        default_acc = 'public' if (outer is not None and outer.kind == 'interface') else 'private'
        mem.access = access_of(mods, default_acc)
        mem.static = 'static' in mods or 'const' in mods
        tmap = outer.tmap() if outer else {}
        mem.rev = {v: k for k, v in tmap.items()}
        i = skip_ws(s, i)
        if i < n and s[i] == '~':
            return None  # finalizer
        if 'implicit' in mods or 'explicit' in mods:
            m = re.compile(r'\s*operator\b').match(s, i)
            if not m:
                return None
            r = read_type(s, m.end())
            if not r:
                return None
            mem.kind = 'conversion'
            mem.ret_raw = r[0]
            mem.ret = norm_type(r[0], tmap)
            mem.name = ('implicit' if 'implicit' in mods else 'explicit') + ' operator ' + mem.ret
            i = skip_ws(s, r[1])
            if i >= n or s[i] != '(':
                return None
            j = match_pair(s, i, '(', ')')
            mem.params = parse_params(s[i + 1:j], tmap)
            return mem
        # return type (or constructor name)
        ref = re.compile(r'ref\s+(readonly\s+)?').match(s, i)
        refp = ''
        if ref:
            refp = 'ref readonly ' if ref.group(1) else 'ref '
            i = ref.end()
        r = read_type(s, i)
        if not r:
            return None
        ttext, i = r
        i = skip_ws(s, i)
        if i < n and s[i] == '(':
            # constructor (or a method with no return type: ignore)
            if outer is None or norm_type(ttext) != outer.name:
                return None
            mem.kind = 'ctor'
            mem.name = outer.name
            j = match_pair(s, i, '(', ')')
            if j < 0:
                return None
            mem.params = parse_params(s[i + 1:j], tmap)
            mem.ret = ''
            return mem
        mem.ret_raw = refp + ttext
        if 'delegate' in mods:
            m = IDENT.match(s, i)
            if not m:
                return None
            mem.kind = 'delegate'
            mem.name = m.group(0).lstrip('@')
            i = skip_ws(s, m.end())
            tp_text = ''
            if i < n and s[i] == '<':
                k = match_angle(s, i)
                tp_text = s[i:k + 1]
                i = skip_ws(s, k + 1)
            mem._tparams = type_params(tp_text)
            full = dict(tmap)
            base = len(outer.all_tparams) if outer else 0
            for k, nm in enumerate(mem._tparams):
                full[nm] = '`%d' % (base + k)
                mem.rev['`%d' % (base + k)] = nm
            mem.ret = norm_type(refp + ttext, full)
            if i < n and s[i] == '(':
                j = match_pair(s, i, '(', ')')
                mem.params = parse_params(s[i + 1:j], full)
                mem.constraints = parse_constraints(s[j + 1:], full)
            return mem
        m = re.compile(r'operator\b').match(s, i)
        if m:
            j = s.find('(', m.end())
            if j < 0:
                return None
            sym = ''.join(s[m.end():j].split())
            mem.kind = 'operator'
            mem.name = 'operator ' + sym
            mem.ret = norm_type(refp + ttext, tmap)
            k = match_pair(s, j, '(', ')')
            mem.params = parse_params(s[j + 1:k], tmap)
            return mem
        m = re.compile(r'this\s*\[').match(s, i)
        if m:
            j = m.end() - 1
            k = match_pair(s, j, '[', ']')
            if k < 0:
                return None
            mem.kind = 'indexer'
            mem.name = 'this[]'
            mem.ret = norm_type(refp + ttext, tmap)
            mem.params = parse_params(s[j + 1:k], tmap)
            return mem
        # member name, possibly generic, possibly an explicit interface implementation
        segs = []
        tp_text = ''
        while True:
            m = IDENT.match(s, i)
            if not m:
                break
            nm = m.group(0).lstrip('@')
            i = skip_ws(s, m.end())
            tp_text = ''
            if i < n and s[i] == '<':
                k = match_angle(s, i)
                if k < 0:
                    return None
                tp_text = s[i:k + 1]
                i = skip_ws(s, k + 1)
            segs.append(nm)
            if i < n and s[i] == '.':
                i = skip_ws(s, i + 1)
                continue
            break
        if not segs:
            return None
        if len(segs) > 1:
            mem.access = 'explicit-interface'
        mem.name = segs[-1] if len(segs) == 1 else '.'.join(segs)
        if i < n and s[i] == '(':
            mtp = type_params(tp_text)
            full = dict(tmap)
            for k, nm in enumerate(mtp):
                full[nm] = '``%d' % k
                mem.rev['``%d' % k] = nm
            mem.kind = 'method'
            mem.garity = len(mtp)
            mem.ret = norm_type(refp + ttext, full)
            j = match_pair(s, i, '(', ')')
            if j < 0:
                return None
            mem.params = parse_params(s[i + 1:j], full)
            mem.constraints = parse_constraints(s[j + 1:], full)
            return mem
        if tp_text:
            return None
        mem.ret = norm_type(refp + ttext, tmap)
        if term in ('{', '=>'):
            mem.kind = 'event' if 'event' in mods else 'property'
            return mem
        if term in (';', 'init'):
            mem.kind = 'event' if 'event' in mods else 'field'
            extra = []
            rest = s[i:]
            if rest.strip():
                # further declarators: "= init, b, c = 3"
                pieces = split_top(rest)
                for p in pieces[1:]:
                    mm = IDENT.match(p.strip())
                    if mm:
                        extra.append(mm.group(0).lstrip('@'))
            if extra:
                mem._extra = extra
            return mem
        return None


def eval_enum_value(text, known):
    s = ' '.join(text.split())
    s = re.sub(r'\((?:int|uint|long|short|byte|sbyte|ushort|ulong)\)', '', s)
    s = re.sub(r'(?<=[0-9a-fA-F])[uUlL]+\b', '', s)

    def repl(m):
        name = m.group(0)
        if re.fullmatch(r'0[xX][0-9a-fA-F]+|\d+', name):
            return name
        key = name.split('.')[-1]
        if key in known and known[key] is not None:
            return str(known[key])
        raise ValueError(name)
    try:
        s = re.sub(r'0[xX][0-9a-fA-F]+|[A-Za-z_][\w.]*|\d+', repl, s)
        if not re.fullmatch(r'[0-9a-fA-FxX\s|&^~<>()+\-*]+', s):
            return None
        return int(eval(s, {'__builtins__': {}}, {}))
    except Exception:
        return None


def parse_params(s, tmap):
    params = []
    i = 0
    n = len(s)
    while True:
        i = skip_ws(s, i)
        if i >= n:
            break
        i, attrs = skip_attributes(s, i)
        mods = []
        while True:
            m = re.compile(r'(this|ref|out|in|params|scoped|readonly)\b\s*').match(s, i)
            if not m:
                break
            if m.group(1) != 'scoped':
                mods.append(m.group(1))
            i = m.end()
        if s.startswith('__arglist', i):
            params.append(('__arglist', False, '__arglist'))
            break
        r = read_type(s, i)
        if not r:
            raise ValueError('cannot read parameter type in (%s)' % s.strip())
        ttext, i = r
        m = IDENT.match(s, skip_ws(s, i))
        if m:
            i = m.end()
        i = skip_ws(s, i)
        optional = bool(re.search(r'\b(DefaultValue|Optional|DefaultParameterValue)\b', attrs))
        if i < n and s[i] == '=':
            optional = True
            depth = 0
            while i < n:
                ch = s[i]
                if ch in '([{':
                    depth += 1
                elif ch in ')]}':
                    depth -= 1
                elif ch == ',' and depth == 0:
                    break
                i += 1
        typ = ' '.join(mods + [norm_type(ttext, tmap)])
        params.append((typ, optional, ' '.join((' '.join(mods) + ' ' + ttext).split())))
        i = skip_ws(s, i)
        if i < n and s[i] == ',':
            i += 1
            continue
        break
    return params


# --------------------------------------------------------------------------------------
# Checker
# --------------------------------------------------------------------------------------

CITE_RE = re.compile(r'//\s*source\s*:\s*(\S+)')


class Roots:
    def __init__(self, specs):
        self.roots = []  # (name, path)
        for spec in specs:
            if '=' in spec and not os.path.exists(spec):
                name, path = spec.split('=', 1)
            else:
                name, path = os.path.basename(os.path.normpath(spec)), spec
            if not os.path.isdir(path):
                raise SystemExit('check_stubs: source root not found: %s' % path)
            self.roots.append((name, os.path.abspath(path)))
        self.names = {n for n, _ in self.roots}
        self._cache = {}
        self._all_files = None
        self._text_cache = {}
        self._type_index = None

    def resolve(self, cite):
        """-> list of (display, abspath)"""
        roots = self.roots
        rel = cite
        m = re.match(r'([A-Za-z0-9_.-]+):(.*)$', cite)
        if m and m.group(1) in self.names:
            roots = [(n, p) for n, p in self.roots if n == m.group(1)]
            rel = m.group(2)
        rel = rel.lstrip('/')
        out = []
        for name, path in roots:
            if any(ch in rel for ch in '*?['):
                hits = sorted(glob.glob(os.path.join(path, rel), recursive=True))
                for h in hits:
                    if os.path.isfile(h):
                        out.append((self.disp(name, path, h), h))
            else:
                full = os.path.join(path, rel)
                if os.path.isfile(full):
                    out.append((self.disp(name, path, full), full))
        return out

    def disp(self, name, root, full):
        rel = os.path.relpath(full, root)
        return '%s:%s' % (name, rel) if len(self.roots) > 1 else rel

    def parse(self, disp, full):
        sf = self._cache.get(full)
        if sf is None:
            sf = SourceFile(full, disp)
            self._cache[full] = sf
        return sf

    def all_files(self):
        if self._all_files is None:
            res = []
            for name, path in self.roots:
                for dp, dn, fn in os.walk(path):
                    dn.sort()
                    for f in sorted(fn):
                        if f.endswith('.cs'):
                            full = os.path.join(dp, f)
                            res.append((self.disp(name, path, full), full))
            self._all_files = res
        return self._all_files

    def text(self, full):
        t = self._text_cache.get(full)
        if t is None:
            try:
                with open(full, encoding='utf-8-sig', errors='replace') as f:
                    t = f.read()
            except OSError:
                t = ''
            self._text_cache[full] = t
        return t

    def type_index(self):
        """type name -> [(display, path)] of files that declare a type (or delegate) of that name"""
        if self._type_index is None:
            idx = {}
            rx = re.compile(r'\b(?:class|struct|interface|enum|record)\s+@?([A-Za-z_]\w*)'
                            r'|\bdelegate\s+[\w<>\[\],.?\s]+?\s([A-Za-z_]\w*)\s*[<(]')
            for disp, full in self.all_files():
                names = set()
                for m in rx.finditer(self.text(full)):
                    names.add(m.group(1) or m.group(2))
                for nm in names:
                    idx.setdefault(nm, []).append((disp, full))
            self._type_index = idx
            self._text_cache = {}
        return self._type_index

    def find_elsewhere(self, words, skip, pred):
        """Search the source files that declare type words[0] and mention the other words;
        return 'file:line' of declarations where pred(decl)."""
        found = []
        for disp, full in self.type_index().get(words[0], []):
            if full in skip:
                continue
            if words[1:]:
                txt = self.text(full)
                if not all(re.search(r'\b%s\b' % re.escape(w), txt) for w in words[1:]):
                    continue
            sf = self.parse(disp, full)
            for x in sf.members + sf.types:
                if pred(x):
                    found.append('%s:%d' % (disp, x.line))
            if len(found) >= 3:
                break
        return found


def citation_for(stub, span):
    """Citation on any line of span, else on comment-only lines directly above."""
    lines = stub.raw.split('\n')
    a, b = span
    for ln in range(a, b + 1):
        if 1 <= ln <= len(lines):
            m = CITE_RE.search(lines[ln - 1])
            if m:
                return m.group(1), ln
    ln = a - 1
    while ln >= 1:
        line = lines[ln - 1].strip()
        if not line.startswith('//') and not (line.startswith('[') and line.endswith(']')):
            break
        m = CITE_RE.search(line)
        if m:
            return m.group(1), ln
        ln -= 1
    return None, None


def member_diffs(st, src):
    d = []
    if st.kind != src.kind:
        d.append('kind %s vs stub %s' % (src.kind, st.kind))
    if st.ret != src.ret:
        d.append('type %s vs stub %s' % (src.pretty(src.ret) or '-', st.pretty(st.ret) or '-'))
    if st.static != src.static:
        d.append('%s in source, %s in stub' % ('static' if src.static else 'instance',
                                               'static' if st.static else 'instance'))
    if access_group(st.access) != access_group(src.access):
        d.append('access %s vs stub %s' % (src.access, st.access))
    for k, (sp, rp) in enumerate(zip(st.params, src.params)):
        if sp[1] and not rp[1]:
            d.append('parameter %d optional in stub only' % (k + 1))
    if st.constraints != src.constraints and (st.constraints or src.constraints):
        d.append('constraints %s vs stub %s' % (src.pretty(fmt_cons(src.constraints)),
                                                 st.pretty(fmt_cons(st.constraints))))
    if st.accessors is not None and src.accessors is not None:
        for acc, a in sorted(st.accessors.items()):
            if acc not in src.accessors:
                d.append("no '%s' accessor in source" % acc)
            elif access_group(src.accessors[acc]) != access_group(a) and access_group(a) != 'non-public':
                d.append("'%s' accessor is %s in source" % (acc, src.accessors[acc]))
    if st.kind == 'enum' and st.value_given and st.value is not None and src.value is not None \
            and st.value != src.value:
        d.append('value %d vs stub %d' % (src.value, st.value))
    return d


def fmt_cons(c):
    return '{' + '; '.join('%s: %s' % (k, ', '.join(v)) for k, v in sorted(c.items())) + '}' if c else '{}'


class Checker:
    def __init__(self, roots, verbose=False, hints=True):
        self.roots = roots
        self.verbose = verbose
        self.hints = hints
        self.mismatches = []
        self.checked = 0
        self.types_checked = 0
        self.ok_lines = []

    def report(self, stub, line, what, cite_disp, detail):
        self.mismatches.append('%s:%d: %s: not found in %s (%s)' % (stub.display, line, what, cite_disp, detail))

    def sources_for(self, cite):
        res = self.roots.resolve(cite)
        return [self.roots.parse(d, f) for d, f in res]

    def check_file(self, stub):
        cites = {}
        for td in stub.types:
            c, _ = citation_for(stub, td.span)
            if c is None and td.outer is not None:
                c = cites.get(id(td.outer))
            cites[id(td)] = c
        for td in stub.types:
            self.check_type(stub, td, cites.get(id(td)), stub.by_type.get(td.key, []))
        for mem in stub.members:
            c, _ = citation_for(stub, mem.span)
            if c is None:
                c = cites.get(id(mem.owner))
            self.check_member(stub, mem, c)
            extra = getattr(mem, '_extra', [])
            for nm in extra:  # "public float x, y, z;"
                clone = Member()
                clone.__dict__.update(mem.__dict__)
                clone.name = nm
                clone._extra = []
                self.check_member(stub, clone, c)

    def check_type(self, stub, td, cite, members):
        self.types_checked += 1
        what = 'type %s%s' % (td.ns + '.' if td.ns else '', td.display())
        if cite is None:
            # use the first member citation, if any
            for mem in members:
                cite, _ = citation_for(stub, mem.span)
                if cite:
                    break
        if cite is None:
            self.report(stub, td.line, what, '-', 'no // source: citation')
            return
        srcs = self.sources_for(cite)
        if not srcs:
            self.report(stub, td.line, what, cite, 'cited file does not exist in any source root')
            return
        found = [t for sf in srcs for t in sf.types if t.key == td.key]
        if not found:
            detail = self.type_hint(td, srcs)
            self.report(stub, td.line, what, cite, detail)
            return
        diffs = []
        kinds = {t.kind for t in found}
        if td.kind not in kinds:
            diffs.append('kind %s vs stub %s' % ('/'.join(sorted(kinds)), td.kind))
        # modifiers of a partial type may be written on one part only: judge only what is known
        all_partial = all('partial' in t.mods for t in found)
        src_static = any(t.static for t in found)
        if td.static != src_static and not (td.static and all_partial):
            diffs.append('%s in source, %s in stub' % ('static' if src_static else 'not static',
                                                       'static' if td.static else 'not static'))
        explicit = [t.access for t in found if set(t.mods) & {'public', 'protected', 'internal', 'private'}]
        src_access = explicit[0] if explicit else (None if all_partial else found[0].access)
        if src_access is not None and access_group(td.access) != access_group(src_access):
            diffs.append('access %s vs stub %s' % (src_access, td.access))
        src_bases = {b for t in found for b in t.bases}
        for b in td.bases:
            if b not in src_bases:
                diffs.append('base %s not declared in source (source: %s)' % (b, ', '.join(sorted(src_bases)) or '-'))
        src_cons = {}
        for t in found:
            src_cons.update(t.constraints)
        if td.constraints != src_cons:
            rev_src = {'`%d' % k: n for k, n in enumerate(found[0].all_tparams)}
            rev_st = {'`%d' % k: n for k, n in enumerate(td.all_tparams)}
            pr = lambda txt, rev: re.sub(r'`\d+', lambda m: rev.get(m.group(0), m.group(0)), txt)
            diffs.append('constraints %s vs stub %s' % (pr(fmt_cons(src_cons), rev_src),
                                                        pr(fmt_cons(td.constraints), rev_st)))
        src_usage = {t.usage for t in found if t.usage is not None}
        src_usage = src_usage.pop() if len(src_usage) == 1 else (None if not src_usage else '|'.join(sorted(src_usage)))
        if td.usage != src_usage:
            diffs.append('AttributeUsage(%s) in source, %s in stub' % (
                src_usage if src_usage is not None else 'none',
                'AttributeUsage(%s)' % td.usage if td.usage is not None else 'none'))
        if td.kind == 'delegate' and td.sig is not None:
            ss = [t.sig for t in found if t.sig is not None]
            if ss and all(member_diffs(td.sig, x) or [p[0] for p in x.params] != [p[0] for p in td.sig.params]
                          for x in ss):
                diffs.append('delegate signature differs (source: %s)' % ss[0].signature())
        if diffs:
            self.report(stub, td.line, what, cite, 'closest: %s %s @ %s:%d; differs: %s' % (
                found[0].kind, found[0].display(), found[0].file, found[0].line, '; '.join(diffs)))
        elif self.verbose:
            self.ok_lines.append('OK %s:%d %s -> %s:%d' % (stub.display, td.line, what, found[0].file, found[0].line))

    def type_hint(self, td, srcs):
        names = {t.display() for sf in srcs for t in sf.types}
        close = difflib.get_close_matches(td.display(), sorted(names), n=3)
        same = [t for sf in srcs for t in sf.types if t.name == td.name]
        bits = []
        if same:
            bits.append('closest: %s %s%s @ %s:%d' % (same[0].kind, same[0].ns + '.' if same[0].ns else '',
                                                      same[0].display(), same[0].file, same[0].line))
        elif close:
            bits.append('closest: ' + ', '.join(close))
        else:
            bits.append('closest: type not declared there')
        if self.hints:
            skip = {sf.path for sf in srcs}
            key = td.key
            where = self.roots.find_elsewhere([td.name], skip, lambda x: isinstance(x, TypeDecl) and x.key == key)
            if where:
                bits.append('type declared in ' + ', '.join(where))
        return '; '.join(bits)

    def check_member(self, stub, mem, cite):
        self.checked += 1
        td = mem.owner
        what = 'member %s' % mem.display()
        if cite is None:
            self.report(stub, mem.line, what, '-', 'no // source: citation')
            return
        srcs = self.sources_for(cite)
        if not srcs:
            self.report(stub, mem.line, what, cite, 'cited file does not exist in any source root')
            return
        cands = [m for sf in srcs for m in sf.by_type.get(td.key, [])]
        have_type = any(td.key in sf.by_type for sf in srcs)
        key = mem.sig_key()
        exact = [m for m in cands if m.sig_key() == key]
        for m in exact:
            if not member_diffs(mem, m):
                if self.verbose:
                    self.ok_lines.append('OK %s:%d %s -> %s:%d' % (stub.display, mem.line, mem.display(), m.file, m.line))
                return
        bits = []
        if exact:
            best = exact[0]
            bits.append('closest: %s @ %s:%d; differs: %s' % (best.signature(), best.file, best.line,
                                                               '; '.join(member_diffs(mem, best))))
        elif not have_type:
            same = [t for sf in srcs for t in sf.types if t.name == td.name]
            if same:
                bits.append('closest: type %s%s declared there, not %s%s' % (
                    same[0].ns + '.' if same[0].ns else '', same[0].display(),
                    td.ns + '.' if td.ns else '', td.display()))
            else:
                bits.append('closest: type %s not declared there' % td.display())
        else:
            same = [m for m in cands if m.name == mem.name]
            if same:
                target = mem.signature()
                same.sort(key=lambda m: (KIND_CAT[m.kind] != KIND_CAT[mem.kind],
                                         -difflib.SequenceMatcher(None, target, m.signature()).ratio()))
                txt = 'closest: ' + ', '.join('%s @ %s:%d' % (m.signature(), m.file, m.line) for m in same[:3])
                if KIND_CAT[same[0].kind] != KIND_CAT[mem.kind]:
                    txt += '; differs: kind %s vs stub %s' % (same[0].kind, mem.kind)
                bits.append(txt)
            else:
                names = sorted({m.name for m in cands})
                close = difflib.get_close_matches(mem.name, names, n=3, cutoff=0.5)
                bits.append('closest: ' + (', '.join(close) if close else 'no member of that name in %s' % td.display()))
        if self.hints:
            skip = {sf.path for sf in srcs}
            tkey = td.key
            words = [td.name] + ([mem.name] if mem.kind not in ('ctor', 'indexer', 'operator', 'conversion') else [])

            def pred(x):
                return isinstance(x, Member) and x.owner is not None and x.owner.key == tkey \
                    and x.sig_key() == key and not member_diffs(mem, x)
            where = self.roots.find_elsewhere(words, skip, pred)
            if where:
                bits.append('matching declaration is in ' + ', '.join(where))
        self.report(stub, mem.line, what, cite, '; '.join(bits))


def main(argv=None):
    ap = argparse.ArgumentParser(
        description='Check C# declaration stubs against real C# sources.',
        epilog='Cite sources in stubs with "// source: [ROOTNAME:]relative/path.cs" (globs allowed).')
    ap.add_argument('stub_dir', help='directory with stub .cs files (searched recursively)')
    ap.add_argument('roots', nargs='+', help='source roots: PATH or NAME=PATH')
    ap.add_argument('-v', '--verbose', action='store_true', help='also print where each member matched')
    ap.add_argument('--no-hints', action='store_true',
                    help='do not search the whole source trees for the right file on a mismatch')
    args = ap.parse_args(argv)
    if not os.path.isdir(args.stub_dir):
        print('check_stubs: stub directory not found: %s' % args.stub_dir, file=sys.stderr)
        return 2
    roots = Roots(args.roots)
    chk = Checker(roots, verbose=args.verbose, hints=not args.no_hints)
    stub_files = []
    for dp, dn, fn in os.walk(args.stub_dir):
        dn.sort()
        for f in sorted(fn):
            if f.endswith('.cs'):
                stub_files.append(os.path.join(dp, f))
    for path in stub_files:
        stub = SourceFile(path, os.path.relpath(path, args.stub_dir), is_stub=True)
        for e in stub.errors:
            chk.mismatches.append(e)
        chk.check_file(stub)
    for line in chk.ok_lines:
        print(line)
    for line in chk.mismatches:
        print(line)
    if args.verbose:
        print('%d types checked' % chk.types_checked)
    print('%d members checked, %d mismatches' % (chk.checked, len(chk.mismatches)))
    return 1 if chk.mismatches else 0


if __name__ == '__main__':
    sys.exit(main())
