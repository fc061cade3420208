#!/usr/bin/env python3
"""mutations.py - prove that the Unity check fails on the mistakes it exists to catch.

Each mutation copies the package's compiled inputs (.cs, .asmdef, csc.rsp, .json, .meta, the docs) into a
temporary folder, plants one mistake, compiles the affected assembly as unity_compile.py does (Core is
reused from the normal run unless the mutation is planted in Core) and, for the rules Unity enforces only at run time,
runs the rules tool; the mutation must fail with the error it names. Mistakes planted: a missing asmdef
reference, an assembly that exists only under a versionDefines define used unguarded (ONNX Runtime, Timeline), a
Timeline type used outside the assembly that guards it, a nullable
annotation without the csc.rsp that enables it, a misplaced attribute, editor API in runtime code (player),
Unity members the stubs lack or with wrong types, a package API that does not exist, a managed field in an
animation job, a main-thread call inside ProcessAnimation, an unserializable [SerializeField], a menu
path the docs name that the package does not declare, internals given to a player assembly, Core's
internals given to an Editor-only assembly.

Usage: mutations.py OUT_DIR RULES_DLL   (OUT_DIR: where unity_compile.py put its assemblies)
"""
import contextlib
import io
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import unity_compile as uc  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
KEEP = ('.cs', '.asmdef', '.asmref', '.rsp', '.json', '.meta', '.md')
SKIP_DIRS = {'.git', 'Tools~', 'Training', 'UnityPackage', 'Fixtures~', 'Models', 'node_modules', 'obj', 'bin'}


def copy_package(dst):
    def ignore(folder, names):
        return [n for n in names if (os.path.isdir(os.path.join(folder, n)) and n in SKIP_DIRS)
                or (os.path.isfile(os.path.join(folder, n)) and not n.endswith(KEEP))]
    shutil.copytree(uc.REPO, dst, ignore=ignore, dirs_exist_ok=True)


def edit_json_list(path, key, add=None, remove=None):
    data = uc.read_json(path)
    items = data.get(key, [])
    if remove:
        items = [x for x in items if x != remove]
    if add:
        items.append(add)
    data[key] = items
    import json
    with open(path, 'w') as f:
        json.dump(data, f, indent=4)


def write(root, rel, text):
    with open(os.path.join(root, rel), 'w') as f:
        f.write(text)


def planted_file(name):
    with open(os.path.join(HERE, 'Mutations', name)) as f:
        return f.read()


JOB_HEAD = 'using UnityEngine.Animations;\nnamespace DeltaInterpolator.Unity.Mutation\n{\n'
MUTATIONS = [
    ('missing asmdef reference (Runtime/Unity without DeltaInterpolator.Core)', 'editor', 'DeltaInterpolator.Unity',
     lambda r: edit_json_list(os.path.join(r, 'Runtime/Unity/DeltaInterpolator.Unity.asmdef'), 'references',
                              remove='DeltaInterpolator.Core'), 'csc', r'error CS02(34|46)'),
    ('versionDefines-guarded assembly used unguarded (DeltaInterpolator.OnnxRuntime from Editor/, no ONNX Runtime package)',
     'editor', 'DeltaInterpolator.Editor',
     lambda r: (edit_json_list(os.path.join(r, 'Editor/DeltaInterpolator.Editor.asmdef'), 'references', add='DeltaInterpolator.OnnxRuntime'),
                write(r, 'Editor/Mutation.cs', 'using DeltaInterpolator.OnnxRuntime;\nnamespace DeltaInterpolator.Editor.Mutation\n{\n'
                      '    internal static class UsesOnnxRuntime\n    {\n        public static System.Type Backend => typeof(OnnxRuntimeBackend);\n    }\n}\n')),
     'csc', r'error CS0234'),
    ('Timeline type used outside the guarded assembly (UnityEngine.Timeline in Runtime/Unity, Timeline installed)',
     'editor+timeline', 'DeltaInterpolator.Unity',
     lambda r: write(r, 'Runtime/Unity/Mutation.cs', 'namespace DeltaInterpolator.Unity.Mutation\n{\n    internal static class UsesTimeline\n    {\n'
                     '        public static System.Type Track => typeof(UnityEngine.Timeline.TrackAsset);\n    }\n}\n'),
     'csc', r'error CS0234'),
    ('versionDefines-guarded Timeline assembly used unguarded (DeltaInterpolator.Timeline from Editor/, no Timeline package)',
     'editor', 'DeltaInterpolator.Editor',
     lambda r: (edit_json_list(os.path.join(r, 'Editor/DeltaInterpolator.Editor.asmdef'), 'references', add='DeltaInterpolator.Timeline'),
                write(r, 'Editor/Mutation.cs', 'using DeltaInterpolator.Timeline;\nnamespace DeltaInterpolator.Editor.Mutation\n{\n'
                      '    internal static class UsesTrack\n    {\n        public static System.Type Track => typeof(NeuralAnimationTrack);\n    }\n}\n')),
     'csc', r'error CS0234'),
    ('nullable annotation without csc.rsp (Runtime/Unity/csc.rsp removed)', 'editor', 'DeltaInterpolator.Unity',
     lambda r: os.remove(os.path.join(r, 'Runtime/Unity/csc.rsp')), 'csc', r'error CS8632'),
    ('misplaced attribute ([MenuItem] on a class)', 'editor', 'DeltaInterpolator.Editor',
     lambda r: write(r, 'Editor/Mutation.cs', 'namespace DeltaInterpolator.Editor.Mutation\n{\n    [UnityEditor.MenuItem("Tools/Misplaced")]\n'
                     '    internal sealed class Misplaced\n    {\n    }\n}\n'), 'csc', r'error CS0592'),
    ('editor API in runtime code (UnityEditor.Undo in Runtime/Unity, player build)', 'player', 'DeltaInterpolator.Unity',
     lambda r: write(r, 'Runtime/Unity/Mutation.cs', 'namespace DeltaInterpolator.Unity.Mutation\n{\n    internal static class EditorOnly\n    {\n'
                     '        public static void Record(UnityEngine.Object o) => UnityEditor.Undo.RecordObject(o, "x");\n    }\n}\n'),
     'csc', r'error CS0(103|234|246)'),
    ('a Unity member the stubs lack (Mutations/MissingMember.cs)', 'editor', 'DeltaInterpolator.Unity',
     lambda r: write(r, 'Runtime/Unity/Mutation.cs', planted_file('MissingMember.cs')), 'csc', r'error CS1061'),
    ('Unity members called with wrong types (Mutations/WrongTypes.cs)', 'editor', 'DeltaInterpolator.Unity',
     lambda r: write(r, 'Runtime/Unity/Mutation.cs', planted_file('WrongTypes.cs')), 'csc', r'error CS1503'),
    ('a guessed package API (Mutations/GuessedApi.cs)', 'editor', 'DeltaInterpolator.Unity',
     lambda r: write(r, 'Runtime/Unity/Mutation.cs', planted_file('GuessedApi.cs')), 'csc', r'error CS1061'),
    ('managed field in an IAnimationJob struct', 'editor', 'DeltaInterpolator.Unity',
     lambda r: write(r, 'Runtime/Unity/Mutation.cs', JOB_HEAD + '    internal struct ManagedJob : IAnimationJob\n    {\n'
                     '        public string Label;\n        public void ProcessAnimation(AnimationStream stream) { }\n'
                     '        public void ProcessRootMotion(AnimationStream stream) { }\n    }\n}\n'), 'rule', r'^job: .*ManagedJob\.Label'),
    ('main-thread Unity API inside ProcessAnimation (through a helper)', 'editor', 'DeltaInterpolator.Unity',
     lambda r: write(r, 'Runtime/Unity/Mutation.cs', JOB_HEAD + '    internal struct ClockJob : IAnimationJob\n    {\n'
                     '        public double Now;\n        public void ProcessAnimation(AnimationStream stream) { Now = Clock.Read(); }\n'
                     '        public void ProcessRootMotion(AnimationStream stream) { }\n    }\n'
                     '    internal static class Clock\n    {\n        public static double Read() => UnityEngine.Time.timeAsDouble;\n    }\n}\n'),
     'rule', r'^thread: .*ClockJob\.ProcessAnimation .*Time\.get_timeAsDouble'),
    ('[SerializeField] on a Dictionary', 'editor', 'DeltaInterpolator.Unity',
     lambda r: write(r, 'Runtime/Unity/Mutation.cs', 'namespace DeltaInterpolator.Unity.Mutation\n{\n'
                     '    internal sealed class Holder : UnityEngine.MonoBehaviour\n    {\n'
                     '        [UnityEngine.SerializeField] private System.Collections.Generic.Dictionary<string, int> table = new System.Collections.Generic.Dictionary<string, int>();\n'
                     '        public int Count => table.Count;\n    }\n}\n'), 'rule', r'^serial: .*Holder\.table'),
    ('internals given to a runtime assembly (Runtime/Unity → DeltaInterpolator.Sentis)', 'editor', 'DeltaInterpolator.Unity',
     lambda r: write(r, 'Runtime/Unity/Mutation.cs', '[assembly: System.Runtime.CompilerServices.InternalsVisibleTo("DeltaInterpolator.Sentis")]\n'),
     'rule', r'^friends: DeltaInterpolator\.Unity gives its internals to DeltaInterpolator\.Sentis'),
    ('Core\'s internals given to an Editor-only assembly (Runtime/Core → DeltaInterpolator.Evaluation)', 'editor', 'DeltaInterpolator.Core',
     lambda r: write(r, 'Runtime/Core/Mutation.cs', '[assembly: System.Runtime.CompilerServices.InternalsVisibleTo("DeltaInterpolator.Evaluation")]\n'),
     'rule', r'^friends: DeltaInterpolator\.Core gives its internals to DeltaInterpolator\.Evaluation, which is not a test assembly'),
    ('a menu the docs name but the package lacks', 'editor', 'DeltaInterpolator.Editor',
     lambda r: open(os.path.join(r, 'README.md'), 'a').write('\nOpen *Window → Animation → No Such Window*.\n'),
     'rule', r'^menu: README\.md:\d+: \*Window → Animation → No Such Window\*'),
    ('a menu a message names but the package lacks', 'editor', 'DeltaInterpolator.Editor',
     lambda r: write(r, 'Editor/MutationMessage.cs', 'namespace DeltaInterpolator.Editor { internal static class MutationMessage { '
                     'internal static string Hint() => "Assign a model (Assets → Create → Δ-Interpolator → No Such Asset)."; } }\n'),
     'rule', r'^menu: DeltaInterpolator\.Editor: DeltaInterpolator\.Editor\.MutationMessage\.Hint says "Assets → Create → Δ-Interpolator → No Such Asset"'),
    ('a menu a tooltip names with > but the package lacks', 'editor', 'DeltaInterpolator.Editor',
     lambda r: write(r, 'Editor/MutationMessage.cs', 'namespace DeltaInterpolator.Editor { internal static class MutationMessage { '
                     '[UnityEngine.Tooltip("The model (Assets > Create > Δ-Interpolator > No Such Asset).")] internal static int Model; } }\n'),
     'rule', r'^menu: DeltaInterpolator\.Editor: DeltaInterpolator\.Editor\.MutationMessage\.Model says "Assets > Create > Δ-Interpolator > No Such Asset"'),
]


def main(argv):
    out, rules = argv[0], argv[1]
    comp = uc.Compiler()
    stubs = uc.build_stubs(comp, os.path.join(out, 'stubs'))
    nunit = uc.find_nunit()
    failed = 0
    for name, cname, target, plant, kind, expect in MUTATIONS:
        # Core is reused from the normal run unless the mutation plants its mistake in Core itself.
        reuse = [n for n in ('DeltaInterpolator.Core', 'DeltaInterpolator.Unity') if n != target]
        prebuilt = {n: os.path.join(out, cname, n + '.dll') for n in reuse}
        with tempfile.TemporaryDirectory(prefix='unity-mutation-') as tmp:
            root = os.path.join(tmp, 'package')
            copy_package(root)
            plant(root)
            buf = io.StringIO()
            with contextlib.redirect_stdout(buf):
                ok, built, order = uc.build_config(comp, root, cname, uc.CONFIGS[cname], os.path.join(tmp, 'out'), stubs, nunit,
                                                   only=target, prebuilt=prebuilt)
            log = buf.getvalue()
            if kind == 'rule' and ok:
                docs = [os.path.join(root, 'README.md')]
                p = subprocess.run(['dotnet', rules, os.path.join(tmp, 'out'), os.path.join(out, 'stubs'), root] + docs,
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
                ok, log = p.returncode == 0, p.stdout
            hit = [l.strip() for l in log.splitlines() if re.search(expect, l.strip())]
            if ok:
                print('unity-check: FAIL: mutation passed the check: %s' % name)
                failed += 1
            elif not hit:
                print('unity-check: FAIL: mutation failed, but not with %s: %s\n%s' % (expect, name, log))
                failed += 1
            else:
                print('unity-check: mutation rejected [%s]: %s: %s' % (cname, name, hit[0][:160]))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
