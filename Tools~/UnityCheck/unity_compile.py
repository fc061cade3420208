#!/usr/bin/env python3
"""unity_compile.py - compile every assembly of the package the way Unity's Editor and players do.

Unity cannot run here, so this reproduces what its script compilation does with the package, from the
package's own files and nothing written by hand per assembly:
  * one C# compilation per `.asmdef` (Editor/Mono/Scripting/ScriptCompilation in UnityCsReference): the
    `.cs` files in its folder and below, minus hidden folders (a name starting with `.` or ending in `~`)
    and minus sub-folders that hold their own `.asmdef`; its `references` (by name or `GUID:`), its
    `defineConstraints` evaluated against the configuration's defines plus its own `versionDefines`
    (evaluated against the packages installed in that configuration) and the defines of its `csc.rsp`,
    its `includePlatforms`/`excludePlatforms`, `noEngineReferences`, `allowUnsafeCode`,
    `overrideReferences`/`precompiledReferences`;
  * a `csc.rsp` beside the `.asmdef` is passed to the compiler (ResponseFileProvider.Get(assembly
    folder), EditorCompilation.UpdateCustomTargetAssembliesResponseFileData); without one nullable is off,
    as Unity passes no /nullable;
  * Unity's defines for the configuration (Editor or a Linux Mono player of 6000.0), C# 9, .NET Standard
    2.1 reference assemblies, Unity's default /nowarn list (PlayerSettings.suppressCommonWarnings:
    0169, 0649, 0282, 1701, 1702), and -warnaserror for the package's own assemblies: zero warnings;
  * every assembly, in the Editor, also sees UnityEditor (runtime code may use it under #if UNITY_EDITOR);
    a player build does not, so editor API used in runtime code fails in the player configurations;
  * the samples (Samples~/NAME, copied into Assets/ when imported) compile into Assembly-CSharp, which
    references every auto-referenced runtime assembly;
  * UnityEngine, UnityEditor, Unity.InferenceEngine, Unity.InferenceEngine.ONNX.Editor and Unity.Timeline are separate
    stub assemblies (Stubs/ASSEMBLY/, checked against the real sources by check_stubs.py); the optional
    package com.github.asus4.onnxruntime is compiled from Tools~/node_modules when a configuration has it.

Configurations: editor and player, each with and without com.github.asus4.onnxruntime, and each with
com.unity.timeline 1.8.10 (Sentis, com.unity.ai.inference 2.4.0, is a declared dependency: always present;
the Unity.Timeline stub assembly is referenced only where Timeline is installed).

Usage: unity_compile.py [--root PACKAGE] [--config NAME ...] [--out DIR] [--rules] [-v]
Exit status 1 when any compilation fails (errors and warnings are printed as the compiler wrote them).
"""
import argparse
import glob
import json
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
STUBS = os.path.join(HERE, 'Stubs')

UNITY_VERSION = '6000.0.40'
# The packages each configuration has installed (name -> version), beside the package under check.
SENTIS = ('com.unity.ai.inference', '2.4.0')
ORT = ('com.github.asus4.onnxruntime', '0.4.9')
# Timeline is optional as ONNX Runtime is: DeltaInterpolator.Timeline compiles only where a project installed it.
TIMELINE = ('com.unity.timeline', '1.8.10')
ORT_DIR = os.path.join(REPO, 'Tools~', 'node_modules', 'com.github.asus4.onnxruntime')


def unity_version_defines(version):
    """UNITY_X_Y_OR_NEWER for every release up to `version`, plus UNITY_X, UNITY_X_Y, UNITY_X_Y_Z."""
    major, minor, patch = version.split('.')
    releases = ['5_3', '5_4', '5_5', '5_6']
    for year, last in ((2017, 4), (2018, 4), (2019, 4), (2020, 3), (2021, 3), (2022, 3), (2023, 3)):
        releases += ['%d_%d' % (year, m) for m in range(1, last + 1)]
    releases.append('%s_%s' % (major, minor))
    out = ['UNITY_%s_OR_NEWER' % r for r in releases]
    return out + ['UNITY_%s' % major, 'UNITY_%s_%s' % (major, minor), 'UNITY_%s_%s_%s' % (major, minor, patch)]


# Unity's scripting defines (docs: "Conditional compilation" / platform #defines) for a 64-bit Linux
# Editor and a Linux Mono player with .NET Standard 2.1 API compatibility.
COMMON = unity_version_defines(UNITY_VERSION) + [
    'UNITY_64', 'PLATFORM_ARCH_64', 'ENABLE_MONO', 'CSHARP_7_3_OR_NEWER', 'NET_STANDARD_2_0', 'NET_STANDARD_2_1',
    'NET_STANDARD', 'NETSTANDARD2_1', 'NETSTANDARD', 'UNITY_STANDALONE_LINUX', 'UNITY_STANDALONE',
    'PLATFORM_STANDALONE_LINUX', 'PLATFORM_STANDALONE']
# Active Input Handling: the Editor configurations compile as "Input Manager (Old)", the player ones as
# "Input System Package (New)" alone, so code on either side of #if ENABLE_LEGACY_INPUT_MANAGER compiles.
EDITOR = ['ENABLE_LEGACY_INPUT_MANAGER','UNITY_EDITOR', 'UNITY_EDITOR_64', 'UNITY_EDITOR_LINUX', 'DEBUG', 'TRACE', 'UNITY_ASSERTIONS',
          # the package sits in the host project's `testables`, so its test assemblies compile in the Editor
          'UNITY_INCLUDE_TESTS']
PLAYER = ['ENABLE_INPUT_SYSTEM']

CONFIGS = {
    'editor+onnxruntime': dict(editor=True, packages=dict([SENTIS, ORT])),
    'editor': dict(editor=True, packages=dict([SENTIS])),
    'player+onnxruntime': dict(editor=False, packages=dict([SENTIS, ORT])),
    'player': dict(editor=False, packages=dict([SENTIS])),
    'editor+timeline': dict(editor=True, packages=dict([SENTIS, TIMELINE])),
    'player+timeline': dict(editor=False, packages=dict([SENTIS, TIMELINE])),
}

# Unity's default warning suppressions (EditorCompilation: PlayerSettings.suppressCommonWarnings).
UNITY_NOWARN = '0169,0649,0282,1701,1702'

# Stub assemblies: name -> (folder under Stubs/, references, editor only)
STUB_ASSEMBLIES = [
    ('UnityEngine', [], False),
    ('UnityEditor', ['UnityEngine'], True),
    ('Unity.InferenceEngine', ['UnityEngine'], False),
    ('Unity.InferenceEngine.ONNX.Editor', ['UnityEngine', 'UnityEditor', 'Unity.InferenceEngine'], True),
    # com.unity.test-framework 1.4.6's runtime assembly ([UnityTest], UnityEngine.TestTools); it references NUnit
    ('UnityEngine.TestRunner', ['UnityEngine', 'nunit.framework'], False),
    ('Unity.Timeline', ['UnityEngine'], False),
]
# Stub assemblies of optional packages: present only in the configurations that install the package.
STUB_PACKAGES = {'Unity.Timeline': TIMELINE[0]}


def hidden(name):
    """Unity skips files and folders whose name starts with '.' or ends with '~', 'cvs' and '*.tmp'."""
    return name.startswith('.') or name.endswith('~') or name.lower() == 'cvs' or name.endswith('.tmp')


# ---------------------------------------------------------------------------------------------------
# versions, defines
# ---------------------------------------------------------------------------------------------------

def parse_version(text):
    parts = re.match(r'^\s*(\d+)(?:\.(\d+))?(?:\.(\d+))?', text)
    if not parts:
        raise ValueError('not a version: %r' % text)
    return tuple(int(p or 0) for p in parts.groups())


def version_matches(expression, version):
    """Unity's versionDefines expression: `1.2.3` means >= 1.2.3; `[a,b]`, `(a,b)`, `[a,b)`, `(a,)` and
    `[a]` are intervals (VersionRangesEvaluators in UnityCsReference)."""
    v = parse_version(version)
    e = expression.strip()
    if not e:
        return True
    if e[0] not in '[(':
        return v >= parse_version(e)
    lo_incl, hi_incl = e[0] == '[', e[-1] == ']'
    inner = e[1:-1]
    if ',' not in inner:
        return v == parse_version(inner)
    lo, hi = (p.strip() for p in inner.split(',', 1))
    if lo and (v < parse_version(lo) if lo_incl else v <= parse_version(lo)):
        return False
    if hi and (v > parse_version(hi) if hi_incl else v >= parse_version(hi)):
        return False
    return True


def constraint_holds(constraint, defines):
    """One defineConstraints entry: `A`, `!A`, or `A || !B`."""
    for term in constraint.split('||'):
        term = term.strip()
        if term.startswith('!'):
            if term[1:].strip() not in defines:
                return True
        elif term in defines:
            return True
    return False


def rsp_defines(rsp_path):
    out = []
    if rsp_path:
        for tok in open(rsp_path, encoding='utf-8').read().split():
            m = re.match(r'^[-/](?:define|d):(.+)$', tok)
            if m:
                out += [d for d in re.split('[;,]', m.group(1)) if d]
    return out


# ---------------------------------------------------------------------------------------------------
# assemblies
# ---------------------------------------------------------------------------------------------------

class Assembly:
    def __init__(self, name, folder, data, files, rsp=None, third_party=False, asmdef=None):
        self.name = name
        self.folder = folder
        self.data = data
        self.files = files
        self.rsp = rsp
        self.third_party = third_party
        self.asmdef = asmdef

    def get(self, key, default):
        v = self.data.get(key)
        return default if v is None else v


def read_json(path):
    with open(path, encoding='utf-8-sig') as f:
        return json.load(f)


def walk_visible(top):
    """Yield (dirpath, filenames) for every folder Unity sees under top."""
    for dp, dn, fn in os.walk(top):
        dn[:] = sorted(d for d in dn if not hidden(d))
        yield dp, sorted(f for f in fn if not hidden(f))


def collect_assemblies(top, third_party=False, predefined=None):
    """The asmdef assemblies under `top` (a folder Unity imports) and the scripts no asmdef owns."""
    asmdefs = {}
    scripts = []
    for dp, fn in walk_visible(top):
        for f in fn:
            if f.endswith('.asmdef'):
                asmdefs[dp] = os.path.join(dp, f)
            elif f.endswith('.cs'):
                scripts.append(os.path.join(dp, f))
    owned = {d: [] for d in asmdefs}
    orphans = []
    for s in scripts:
        d = os.path.dirname(s)
        while True:
            if d in asmdefs:
                owned[d].append(s)
                break
            if os.path.normpath(d) == os.path.normpath(top) or os.path.dirname(d) == d:
                orphans.append(s)
                break
            d = os.path.dirname(d)
    result = []
    for d, path in sorted(asmdefs.items()):
        data = read_json(path)
        rsp = os.path.join(d, 'csc.rsp')
        result.append(Assembly(data['name'], d, data, sorted(owned[d]),
                               rsp if os.path.isfile(rsp) else None, third_party, path))
    if orphans and predefined:
        result.append(Assembly(predefined, top, {'name': predefined, 'autoReferenced': False}, sorted(orphans),
                               os.path.join(top, 'csc.rsp') if os.path.isfile(os.path.join(top, 'csc.rsp')) else None))
        orphans = []
    return result, orphans


def guid_names(assemblies):
    out = {}
    for a in assemblies:
        if a.asmdef and os.path.isfile(a.asmdef + '.meta'):
            m = re.search(r'^guid:\s*([0-9a-f]{32})', open(a.asmdef + '.meta').read(), re.M)
            if m:
                out['GUID:' + m.group(1)] = a.name
    return out


# ---------------------------------------------------------------------------------------------------
# the compiler
# ---------------------------------------------------------------------------------------------------

def find_csc():
    dotnet = shutil.which('dotnet')
    if not dotnet:
        sys.exit('unity_compile: dotnet is not on PATH')
    base = os.path.dirname(os.path.realpath(dotnet))
    cands = sorted(glob.glob(os.path.join(base, 'sdk', '*', 'Roslyn', 'bincore', 'csc.dll')),
                   key=lambda p: parse_version(p.split(os.sep)[-4]))
    if not cands:
        sys.exit('unity_compile: no Roslyn csc.dll under %s/sdk' % base)
    return dotnet, cands[-1]


def nuget_root():
    return os.environ.get('NUGET_PACKAGES') or os.path.expanduser('~/.nuget/packages')


def find_netstandard():
    for d in (os.path.join(nuget_root(), 'netstandard.library.ref', '2.1.0', 'ref', 'netstandard2.1'),
              os.path.join(os.path.dirname(os.path.realpath(shutil.which('dotnet') or '/')), 'packs',
                           'NETStandard.Library.Ref', '2.1.0', 'ref', 'netstandard2.1')):
        if os.path.isfile(os.path.join(d, 'netstandard.dll')):
            return sorted(glob.glob(os.path.join(d, '*.dll')))
    return None


def find_nunit():
    c = sorted(glob.glob(os.path.join(nuget_root(), 'nunit', '3.*', 'lib', 'netstandard2.0', 'nunit.framework.dll')))
    return c[-1] if c else None


class Compiler:
    def __init__(self, verbose=False):
        self.dotnet, self.csc = find_csc()
        self.netstandard = find_netstandard()
        if not self.netstandard:
            # the .NET Standard 2.1 reference pack arrives with the first restore of a netstandard2.1 project
            subprocess.run(['dotnet', 'restore', os.path.join(REPO, 'Tools~', 'Core', 'DeltaInterpolator.Core.csproj'),
                            '-nologo', '-v', 'q'], check=False)
            self.netstandard = find_netstandard()
            if not self.netstandard:
                sys.exit('unity_compile: the .NET Standard 2.1 reference assemblies (NETStandard.Library.Ref 2.1.0) are missing')
        self.verbose = verbose

    def compile(self, out, files, refs, defines, rsp=None, unsafe=False, warnaserror=True, nowarn=None, extra=()):
        args = [self.dotnet, self.csc, '-nologo', '-noconfig', '-nostdlib+', '-target:library', '-langversion:9',
                '-deterministic', '-nowarn:' + (nowarn or UNITY_NOWARN), '-out:' + out]
        args += ['-warnaserror+'] if warnaserror else ['-warn:0']
        if unsafe:
            args.append('-unsafe+')
        if defines:
            args.append('-define:' + ';'.join(defines))
        args += ['-reference:' + r for r in list(self.netstandard) + list(refs)]
        args += list(extra)
        if rsp:
            args.append('@' + rsp)
        args += files
        p = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        lines = [l for l in p.stdout.splitlines() if l.strip()]
        return p.returncode == 0, lines


# ---------------------------------------------------------------------------------------------------
# one configuration
# ---------------------------------------------------------------------------------------------------

def build_stubs(comp, outdir):
    os.makedirs(outdir, exist_ok=True)
    built = {}
    nunit = find_nunit()
    if nunit:
        built['nunit.framework'] = nunit
    ok = True
    for name, refs, _ in STUB_ASSEMBLIES:
        if any(r not in built for r in refs):
            print('unity-check: FAIL: stub assembly %s needs %s (restore Tools~/Tests first for nunit.framework.dll)'
                  % (name, ', '.join(r for r in refs if r not in built)))
            ok = False
            continue
        files = sorted(glob.glob(os.path.join(STUBS, name, '**', '*.cs'), recursive=True))
        out = os.path.join(outdir, name + '.dll')
        newest = max([os.path.getmtime(f) for f in files] + [os.path.getmtime(__file__)])
        if not (os.path.isfile(out) and os.path.getmtime(out) >= newest and all(
                os.path.getmtime(built[r]) <= os.path.getmtime(out) for r in refs)):
            good, lines = comp.compile(out, files, [built[r] for r in refs], [], nowarn='0660,0661,' + UNITY_NOWARN)
            if not good:
                print('unity-check: FAIL: stub assembly %s does not compile:' % name)
                print('\n'.join('  ' + l for l in lines))
                ok = False
                continue
        built[name] = out
    built.pop('nunit.framework', None)
    return built if ok else None


def plan(root, config):
    """All assemblies Unity would compile for `config`, in dependency order, with their references."""
    editor = config['editor']
    packages = dict(config['packages'])
    problems = []
    ours, orphans = collect_assemblies(root)
    for o in orphans:
        problems.append('%s: a script outside every .asmdef; Unity does not compile it in a package'
                        % os.path.relpath(o, root))
    samples = []
    samples_dir = os.path.join(root, 'Samples~')
    if os.path.isdir(samples_dir):
        for s in sorted(os.listdir(samples_dir)):
            if os.path.isdir(os.path.join(samples_dir, s)) and not hidden(s):
                a, _ = collect_assemblies(os.path.join(samples_dir, s), predefined='Assembly-CSharp')
                for x in a:
                    if x.name == 'Assembly-CSharp':
                        x.name = 'Assembly-CSharp.' + s  # each sample on its own (importing one is enough)
                samples += a
    third = []
    if ORT[0] in packages:
        if not os.path.isdir(ORT_DIR):
            problems.append('%s is missing: run `npm ci --prefix Tools~`' % ORT_DIR)
        else:
            third, _ = collect_assemblies(ORT_DIR, third_party=True)
            third = [t for t in third if t.name == ORT[0]]
    all_asm = ours + samples + third
    guids = guid_names(all_asm)
    base_defines = COMMON + (EDITOR if editor else PLAYER)

    def platform_ok(a):
        inc = a.get('includePlatforms', [])
        exc = a.get('excludePlatforms', [])
        here = 'Editor' if editor else 'LinuxStandalone64'
        if inc:
            return here in inc
        return here not in exc

    selected = []
    for a in all_asm:
        if not platform_ok(a):
            continue
        vdefs = []
        for vd in a.get('versionDefines', []):
            pkg = vd.get('name', '')
            have = UNITY_VERSION if pkg == 'Unity' else packages.get(pkg)
            if have is not None and version_matches(vd.get('expression', ''), have):
                vdefs.append(vd['define'])
        a.defines = base_defines + vdefs + rsp_defines(a.rsp)
        if all(constraint_holds(c, set(a.defines)) for c in a.get('defineConstraints', [])):
            selected.append(a)
    present = {a.name for a in selected}
    stub_present = {n for n, _, ed in STUB_ASSEMBLIES if (editor or not ed) and STUB_PACKAGES.get(n, SENTIS[0]) in packages}
    known_elsewhere = {a.name for a in all_asm} | {n for n, _, _ in STUB_ASSEMBLIES} | {ORT[0]}
    for a in selected:
        names = []
        for r in a.get('references', []):
            r = guids.get(r, r)
            if r in present or r in stub_present:
                names.append(r)
            elif r not in known_elsewhere:
                problems.append('%s: reference %r names no assembly Unity knows in any configuration'
                                % (os.path.relpath(a.asmdef, root) if a.asmdef else a.name, r))
            # else: an assembly this configuration does not compile (Unity drops such a reference)
        if a.name.startswith('Assembly-CSharp'):
            names = [b.name for b in selected if b.get('autoReferenced', True) and not b.name.startswith('Assembly-CSharp')
                     and 'Editor' not in b.get('includePlatforms', [])]
            names += ['Unity.InferenceEngine']  # its asmdef is autoReferenced
            names += [n for n in STUB_PACKAGES if n in stub_present]  # so is Timeline's, where installed
        a.refs = names
    # dependency order
    order, seen = [], set()
    by_name = {a.name: a for a in selected}

    def visit(a, stack=()):
        if a.name in seen:
            return
        if a.name in stack:
            problems.append('reference cycle: ' + ' -> '.join(stack + (a.name,)))
            return
        for r in a.refs:
            if r in by_name:
                visit(by_name[r], stack + (a.name,))
        seen.add(a.name)
        order.append(a)
    for a in selected:
        visit(a)
    return order, problems, all_asm


def build_config(comp, root, cname, config, outdir, stubs, nunit, verbose=False, only=None, prebuilt=None):
    """Compile one configuration; `only`: just that assembly and what it references."""
    order, problems, all_asm = plan(root, config)
    if only:
        by_name = {a.name: a for a in order}
        keep, todo = set(), [only]
        while todo:
            n = todo.pop()
            if n in by_name and n not in keep:
                keep.add(n)
                todo += by_name[n].refs
        if only not in keep:
            problems.append('%s is not compiled in this configuration' % only)
        order = [a for a in order if a.name in keep]
    ok = not problems
    for p in problems:
        print('unity-check: FAIL [%s]: %s' % (cname, p))
    os.makedirs(outdir, exist_ok=True)
    built = {}
    for a in order:
        out = os.path.join(outdir, a.name + '.dll')
        if prebuilt and a.name in prebuilt:
            shutil.copy2(prebuilt[a.name], out)  # unchanged sources, already compiled for this configuration
            built[a.name] = out
            continue
        refs = []
        if not a.get('noEngineReferences', False):
            refs.append(stubs['UnityEngine'])
            if config['editor']:
                refs.append(stubs['UnityEditor'])
        for r in a.refs:
            if r in built:
                refs.append(built[r])
            elif r in stubs:
                refs.append(stubs[r])
            elif r in {b.name for b in order}:
                pass  # failed to build: reported there
        precompiled = a.get('precompiledReferences', []) if a.get('overrideReferences', False) else []
        if 'TestAssemblies' in a.get('optionalUnityReferences', []) or 'nunit.framework.dll' in precompiled:
            if not nunit:
                print('unity-check: FAIL [%s] %s: nunit.framework.dll is missing (restore Tools~/Tests first)' % (cname, a.name))
                ok = False
                continue
            refs.append(nunit)
            # Unity's test assemblies (optionalUnityReferences: TestAssemblies) also see the test framework's runtime
            # assembly, as one that names it in `references` does
            if 'TestAssemblies' in a.get('optionalUnityReferences', []) and not a.get('noEngineReferences', False) \
                    and stubs['UnityEngine.TestRunner'] not in refs:
                refs.append(stubs['UnityEngine.TestRunner'])
        if not a.files:
            continue
        good, lines = comp.compile(out, a.files, refs, a.defines, rsp=a.rsp, unsafe=a.get('allowUnsafeCode', False),
                                   warnaserror=not a.third_party)
        rel = lambda l: l.replace(root + os.sep, '')
        shown = [rel(l) for l in lines if (': error ' in l or ': warning ' in l or not good)]
        if good and not (shown and not a.third_party):
            built[a.name] = out
            if verbose:
                print('unity-check: [%s] %s: %d files, references %s' % (cname, a.name, len(a.files), ', '.join(a.refs) or '-'))
        else:
            ok = False
            print('unity-check: FAIL [%s] %s (%d files%s):' % (cname, a.name, len(a.files), ', csc.rsp' if a.rsp else ''))
            print('\n'.join('  ' + l for l in shown[:60]))
            if len(shown) > 60:
                print('  ... %d more' % (len(shown) - 60))
    # What the rules tool needs to know of each assembly of the package, compiled here or not
    # (InternalsVisibleTo may name only tests and, outside Core, Editor-only assemblies).
    with open(os.path.join(outdir, 'assemblies.json'), 'w') as f:
        json.dump({a.name: {'editorOnly': a.get('includePlatforms', []) == ['Editor'],
                            'test': 'UNITY_INCLUDE_TESTS' in a.get('defineConstraints', [])}
                   for a in all_asm if not a.third_party}, f, indent=1, sort_keys=True)
    return ok, built, order


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--root', default=REPO, help='the package folder (default: this repository)')
    ap.add_argument('--config', action='append', choices=sorted(CONFIGS), help='only these configurations')
    ap.add_argument('--out', default=os.path.join(HERE, 'obj', 'unity'), help='where the assemblies go')
    ap.add_argument('-v', '--verbose', action='store_true')
    args = ap.parse_args(argv)
    comp = Compiler(args.verbose)
    root = os.path.abspath(args.root)
    stubs = build_stubs(comp, os.path.join(args.out, 'stubs'))
    if stubs is None:
        return 1
    nunit = find_nunit()
    failed = False
    for cname in args.config or list(CONFIGS):
        ok, built, order = build_config(comp, root, cname, CONFIGS[cname], os.path.join(args.out, cname), stubs, nunit,
                                        args.verbose)
        names = [a.name for a in order if not a.third_party]
        print('unity-check: [%s] %s: %s' % (cname, 'ok' if ok else 'FAILED', ', '.join(names)))
        failed |= not ok
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
