using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Reflection.Emit;
using System.Runtime.Loader;
using System.Text.Json;
using System.Text.RegularExpressions;

// Rules that Unity checks only when the game runs (or never), held on the compiled package assemblies:
//   job      every IAnimationJob struct holds only unmanaged or native-container fields (Unity refuses
//            managed fields when it creates the AnimationScriptPlayable);
//   thread   nothing that ProcessAnimation/ProcessRootMotion calls, through the package's own code, calls a
//            Unity API outside the animation-stream and math types (jobs run on worker threads);
//   serial   [SerializeField] fields (and public fields of UnityEngine.Object types) have types Unity serializes;
//   menu     every menu path the docs name (*Add Component → …*, *Assets → Create → …*, *Window → …*)
//            exists as an AddComponentMenu/CreateAssetMenu/MenuItem attribute (or, for Add Component, as
//            the nicified name of a MonoBehaviour); so does every menu path the package's own messages name
//            (string literals in its compiled code and string arguments of its attributes such as [Tooltip],
//            with → or > between the steps: "… (Assets > Create > Δ-Interpolator > …)");
//   package  package.json's documentationUrl/changelogUrl/licensesUrl are absolute http(s) links or absent;
//   friends  [InternalsVisibleTo] of DeltaInterpolator.Core names only test assemblies (what the Editor-only
//            assemblies and the tools use of Core is its public API); of another package assembly, only test
//            assemblies and Editor-only ones (assemblies.json, written by unity_compile.py beside the
//            assemblies, says which is which).
// Usage: DeltaInterpolator.UnityRules ASSEMBLY_DIR STUB_DIR PACKAGE_ROOT [DOC.md ...]
// Prints one line per violation; exit 1 when there is any.
static class Program
{
    static readonly List<string> Violations = new();
    static readonly HashSet<string> StubNames = new() { "UnityEngine", "UnityEditor", "Unity.InferenceEngine", "Unity.InferenceEngine.ONNX.Editor", "Unity.Timeline" };

    static int Main(string[] args)
    {
        if (args.Length < 3) { Console.Error.WriteLine("usage: DeltaInterpolator.UnityRules ASSEMBLY_DIR STUB_DIR PACKAGE_ROOT [DOC.md ...]"); return 2; }
        string dir = args[0], stubDir = args[1], root = args[2];
        var context = new AssemblyLoadContext("unity-rules");
        context.Resolving += (ctx, name) =>
        {
            foreach (var d in new[] { dir, stubDir })
            {
                var p = Path.Combine(d, name.Name + ".dll");
                if (File.Exists(p)) return ctx.LoadFromAssemblyPath(Path.GetFullPath(p));
            }
            return null;
        };
        var package = Directory.GetFiles(dir, "*.dll").OrderBy(p => p, StringComparer.Ordinal)
            .Select(p => context.LoadFromAssemblyPath(Path.GetFullPath(p)))
            .Where(a => a.GetName().Name!.StartsWith("DeltaInterpolator.") || a.GetName().Name!.StartsWith("Assembly-CSharp"))
            .Where(a => !a.GetName().Name!.EndsWith(".Tests"))
            .ToList();
        var types = package.SelectMany(Types).ToList();
        foreach (var t in types) CheckJob(t, types);
        foreach (var t in types) CheckSerialized(t);
        // Menu items live in the Editor assembly: a player configuration has none to hold the docs against.
        if (package.Any(a => a.GetName().Name == "DeltaInterpolator.Editor")) CheckMenus(types, args.Skip(3).ToList(), root, OptionalMenus(dir, stubDir));
        CheckPackageJson(root);
        CheckFriends(package, dir);
        foreach (var v in Violations) Console.WriteLine(v);
        Console.WriteLine($"unity-rules: {package.Count} assemblies, {types.Count} types, {Violations.Count} violation(s)");
        return Violations.Count == 0 ? 0 : 1;
    }

    static IEnumerable<Type> Types(Assembly a)
    {
        try { return a.GetTypes(); }
        catch (ReflectionTypeLoadException e) { return e.Types.Where(t => t != null)!; }
    }

    static bool IsStub(Type t) => StubNames.Contains(t.Assembly.GetName().Name!);
    static bool IsPackage(Type t) => t.Assembly.GetName().Name!.StartsWith("DeltaInterpolator.");
    const BindingFlags All = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;

    // ---- job -----------------------------------------------------------------------------------------
    static void CheckJob(Type t, List<Type> types)
    {
        if (!t.IsValueType || !t.GetInterfaces().Any(i => i.FullName == "UnityEngine.Animations.IAnimationJob")) return;
        foreach (var f in t.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic))
            if (!JobSafe(f.FieldType, new HashSet<Type>()))
                Violations.Add($"job: {t.FullName}.{f.Name} is a {Name(f.FieldType)}: an IAnimationJob struct may hold only unmanaged values and native containers (Unity refuses the job otherwise)");
        foreach (var name in new[] { "ProcessAnimation", "ProcessRootMotion" })
        {
            var m = t.GetMethod(name, BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic);
            if (m != null) WalkCalls(m, $"{t.Name}.{name}", types, new HashSet<MethodBase>(), 0);
        }
    }

    static bool JobSafe(Type t, HashSet<Type> seen)
    {
        if (t.IsPointer || t.IsPrimitive || t.IsEnum) return true;
        if (!t.IsValueType) return false;
        if (t.Namespace == "Unity.Collections" && t.Name.StartsWith("Native")) return true;
        if (!seen.Add(t)) return true;
        return t.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic).All(f => JobSafe(f.FieldType, seen));
    }

    // ---- thread --------------------------------------------------------------------------------------
    static readonly string[] ThreadSafeNamespaces = { "UnityEngine.Animations", "UnityEngine.Experimental.Animations", "Unity.Collections" };
    static readonly string[] ThreadSafeTypes = { "UnityEngine.Vector3", "UnityEngine.Quaternion", "UnityEngine.Mathf", "UnityEngine.Vector4", "UnityEngine.Matrix4x4" };

    static void WalkCalls(MethodBase m, string path, List<Type> types, HashSet<MethodBase> seen, int depth)
    {
        if (depth > 12 || !seen.Add(m)) return;
        foreach (var callee in Callees(m))
        {
            var dt = callee.DeclaringType;
            if (dt == null) continue;
            if (IsStub(dt))
            {
                if (!ThreadSafeNamespaces.Contains(dt.Namespace) && !ThreadSafeTypes.Contains(dt.FullName))
                    Violations.Add($"thread: {path} → {Name(dt)}.{callee.Name}: a Unity API that is not for animation jobs (they run off the main thread)");
                continue;
            }
            if (!IsPackage(dt)) continue;
            var next = $"{path} → {dt.Name}.{callee.Name}";
            if (callee.IsAbstract || dt.IsInterface)
            {
                foreach (var impl in Implementations(callee, types)) WalkCalls(impl, next, types, seen, depth + 1);
            }
            else WalkCalls(callee, next, types, seen, depth + 1);
        }
    }

    static IEnumerable<MethodBase> Implementations(MethodBase abstractMethod, List<Type> types)
    {
        var dt = abstractMethod.DeclaringType!;
        var def = dt.IsGenericType ? dt.GetGenericTypeDefinition() : dt;
        foreach (var t in types)
        {
            if (t.IsInterface || t.IsAbstract && !t.IsSealed) continue;
            if (dt.IsInterface)
            {
                foreach (var i in t.GetInterfaces().Where(i => (i.IsGenericType ? i.GetGenericTypeDefinition() : i) == def))
                {
                    InterfaceMapping map;
                    try { map = t.GetInterfaceMap(i); } catch { continue; }
                    for (int k = 0; k < map.InterfaceMethods.Length; k++)
                        if (map.InterfaceMethods[k].Name == abstractMethod.Name) yield return map.TargetMethods[k];
                }
            }
            else if (dt.IsAssignableFrom(t))
            {
                foreach (var m in t.GetMethods(All).Where(m => m.Name == abstractMethod.Name && m.GetBaseDefinition().DeclaringType == dt))
                    yield return m;
            }
        }
    }

    static readonly Dictionary<short, OpCode> OpCodesByValue = typeof(OpCodes).GetFields(BindingFlags.Public | BindingFlags.Static)
        .Select(f => (OpCode)f.GetValue(null)!).ToDictionary(o => o.Value);

    static IEnumerable<MethodBase> Callees(MethodBase m)
    {
        byte[]? il;
        try { il = m.GetMethodBody()?.GetILAsByteArray(); } catch { il = null; }
        if (il == null) yield break;
        Type[]? typeArgs = m.DeclaringType is { IsGenericType: true } d ? d.GetGenericArguments() : null;
        Type[]? methodArgs = m.IsGenericMethod ? m.GetGenericArguments() : null;
        int i = 0;
        while (i < il.Length)
        {
            short code = il[i] == 0xFE ? (short)(0xFE00 | il[i + 1]) : il[i];
            i += il[i] == 0xFE ? 2 : 1;
            if (!OpCodesByValue.TryGetValue(code, out var op)) yield break;
            int size = op.OperandType switch
            {
                OperandType.InlineNone => 0,
                OperandType.ShortInlineBrTarget or OperandType.ShortInlineI or OperandType.ShortInlineVar => 1,
                OperandType.InlineVar => 2,
                OperandType.InlineI8 or OperandType.InlineR => 8,
                OperandType.InlineSwitch => 4 + 4 * BitConverter.ToInt32(il, i),
                _ => 4,
            };
            if (op.OperandType == OperandType.InlineMethod)
            {
                MethodBase? callee = null;
                try { callee = m.Module.ResolveMethod(BitConverter.ToInt32(il, i), typeArgs, methodArgs); } catch { }
                if (callee != null) yield return callee;
            }
            i += size;
        }
    }

    // ---- serial --------------------------------------------------------------------------------------
    static bool IsUnityObject(Type? t)
    {
        for (; t != null; t = t.BaseType) if (t.FullName == "UnityEngine.Object") return true;
        return false;
    }

    static void CheckSerialized(Type t)
    {
        bool unityObject = IsUnityObject(t);
        foreach (var f in t.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly))
        {
            bool marked = f.CustomAttributes.Any(a => a.AttributeType.FullName == "UnityEngine.SerializeField");
            bool implicitField = unityObject && f.IsPublic && !f.IsNotSerialized && !f.IsInitOnly;
            if (!marked && !implicitField) continue;
            if (f.IsStatic || f.IsInitOnly)
            {
                Violations.Add($"serial: {t.FullName}.{f.Name}: [SerializeField] on a {(f.IsStatic ? "static" : "readonly")} field, which Unity never serializes");
                continue;
            }
            var why = Unserializable(f.FieldType, true);
            if (why != null) Violations.Add($"serial: {t.FullName}.{f.Name} is a {Name(f.FieldType)}: Unity does not serialize it ({why})");
        }
    }

    static string? Unserializable(Type t, bool allowCollection)
    {
        if (t.IsPrimitive || t.IsEnum || t == typeof(string)) return null;
        if (t.IsArray || t.IsGenericType && t.GetGenericTypeDefinition().FullName == "System.Collections.Generic.List`1")
        {
            if (!allowCollection) return "a collection of collections";
            if (t.IsArray && t.GetArrayRank() != 1) return "a multi-dimensional array";
            return Unserializable(t.IsArray ? t.GetElementType()! : t.GetGenericArguments()[0], false);
        }
        if (IsUnityObject(t)) return null;
        if (IsStub(t)) return t.IsValueType || t.FullName is "UnityEngine.AnimationCurve" or "UnityEngine.Gradient" ? null : "a Unity type that is not serializable";
        if (t.Namespace != null && t.Namespace.StartsWith("System")) return "a .NET type other than a primitive, string, array or List<T>";
        if (t.IsInterface || t.IsAbstract) return "an interface or abstract type (needs [SerializeReference])";
        if (!t.IsSerializable) return "its type lacks [System.Serializable]";
        return null;
    }

    // ---- menu ----------------------------------------------------------------------------------------
    static readonly Regex MenuPath = new(@"\*((?:Add Component|Assets|Window|GameObject|Component|Tools) → [^*\n]+)\*");
    // Unity's own menus the docs walk through: the path and everything below it are Unity's.
    // (Test Runner: com.unity.test-framework 1.4.6, UnityEditor.TestRunner/TestRunnerWindow.cs:72.)
    static readonly string[] UnityOwnMenus = { "Window → Package Manager", "Window → Sequencing", "Window → General → Test Runner" };
    // Unity's own sub-menus the docs name as a place ("the baker is under *Window → Animation*"): only the bare path is Unity's.
    static readonly string[] UnitySubMenus = { "Window → Animation", "Window → General" };
    // A menu path inside a message: a top-level menu (or the Project window's Create menu, which is Assets → Create, or
    // Unity's Project Settings window) and its items, up to what ends a phrase in a sentence.
    // Messages write the steps with → or with > ("Assets > Create > …").
    static readonly Regex MessageMenuPath = new(@"\b((?:Add Component|Assets|Create|Window|GameObject|Component|Tools|Edit|File|Project Settings) (?:→|>) [^""().;:,\n]+)");
    static readonly Regex MessageMenuStep = new(@"\s+(?:→|>)\s+");
    // Unity's own windows the messages walk through.
    // (Window → Animation → Animation: Unity's Animation window, which a message may name mid-sentence.)
    static readonly string[] UnityOwnMessageMenus = { "Window/Package Manager", "Window/Animation/Animation", "Window/Sequencing", "Project Settings", "Edit/Project Settings", "File" };

    // Menus declared by assemblies an optional package brings (the Timeline demo's builder): declared in another Editor
    // configuration beside this one (unity_compile.py's editor+timeline), so a doc naming them is right there.
    static List<string> OptionalMenus(string dir, string stubDir)
    {
        var items = new List<string>();
        string? parent = Path.GetDirectoryName(Path.GetFullPath(dir).TrimEnd(Path.DirectorySeparatorChar));
        if (parent == null) return items;
        foreach (var other in Directory.GetDirectories(parent, "editor*"))
        {
            if (Path.GetFullPath(other).TrimEnd(Path.DirectorySeparatorChar) == Path.GetFullPath(dir).TrimEnd(Path.DirectorySeparatorChar)) continue;
            var context = new AssemblyLoadContext("unity-rules-" + Path.GetFileName(other), isCollectible: true);
            context.Resolving += (ctx, name) =>
            {
                foreach (var d in new[] { other, stubDir })
                {
                    var p = Path.Combine(d, name.Name + ".dll");
                    if (File.Exists(p)) return ctx.LoadFromAssemblyPath(Path.GetFullPath(p));
                }
                return null;
            };
            foreach (var path in Directory.GetFiles(other, "DeltaInterpolator.*.dll"))
            {
                if (File.Exists(Path.Combine(dir, Path.GetFileName(path)))) continue; // compiled here too: its menus count here already
                if (Path.GetFileNameWithoutExtension(path).EndsWith(".Tests")) continue; // as for this configuration: tests declare no menus
                try
                {
                    foreach (var t in Types(context.LoadFromAssemblyPath(Path.GetFullPath(path))))
                        foreach (var m in t.GetMethods(All))
                            foreach (var a in m.CustomAttributes.Where(a => a.AttributeType.FullName == "UnityEditor.MenuItem" && a.ConstructorArguments.Count > 0))
                                items.Add((string)a.ConstructorArguments[0].Value!);
                }
                catch (FileNotFoundException)
                {
                    // An assembly whose references that configuration alone has: its menus stay unknown here, so a doc naming one is reported.
                }
            }
        }
        return items;
    }

    static void CheckMenus(List<Type> types, List<string> docs, string root, List<string> optionalMenus)
    {
        var menuItems = new List<string>(optionalMenus);
        var addComponent = new List<string>();
        var createAsset = new List<string>();
        foreach (var t in types)
        {
            foreach (var a in t.CustomAttributes)
            {
                if (a.AttributeType.FullName == "UnityEngine.AddComponentMenu" && a.ConstructorArguments.Count > 0)
                    addComponent.Add((string)a.ConstructorArguments[0].Value!);
                if (a.AttributeType.FullName == "UnityEngine.CreateAssetMenuAttribute")
                    createAsset.AddRange(a.NamedArguments.Where(n => n.MemberName == "menuName").Select(n => (string)n.TypedValue.Value!));
            }
            if (IsUnityObject(t) && !t.IsAbstract && Types(t.Assembly).Contains(t) && IsMonoBehaviour(t) && !t.CustomAttributes.Any(a => a.AttributeType.FullName == "UnityEngine.AddComponentMenu"))
                addComponent.Add("Scripts/" + Nicify(t.Name));
            foreach (var m in t.GetMethods(All))
                foreach (var a in m.CustomAttributes.Where(a => a.AttributeType.FullName == "UnityEditor.MenuItem" && a.ConstructorArguments.Count > 0))
                    menuItems.Add((string)a.ConstructorArguments[0].Value!);
        }
        foreach (var doc in docs)
        {
            var lines = File.ReadAllLines(doc);
            for (int n = 0; n < lines.Length; n++)
                foreach (Match match in MenuPath.Matches(lines[n]))
                {
                    var parts = match.Groups[1].Value.Split(" → ").Select(p => p.Trim().TrimEnd('…')).ToArray();
                    var where = $"{Path.GetRelativePath(root, doc)}:{n + 1}: *{match.Groups[1].Value}*";
                    string rest = string.Join("/", parts.Skip(1));
                    bool ok;
                    if (parts[0] == "Add Component") ok = addComponent.Contains(rest) || addComponent.Contains("Scripts/" + rest);
                    else if (parts[0] == "Assets" && parts.Length > 2 && parts[1] == "Create") ok = createAsset.Contains(string.Join("/", parts.Skip(2)));
                    else
                    {
                        var full = string.Join("/", parts);
                        ok = menuItems.Any(p => p == full || p.StartsWith(full + "/"))
                             || UnityOwnMenus.Any(u => match.Groups[1].Value.StartsWith(u))
                             || UnitySubMenus.Contains(match.Groups[1].Value.Trim());
                    }
                    if (!ok) Violations.Add($"menu: {where} names a menu the package does not declare (MenuItem: {string.Join(", ", menuItems)}; AddComponentMenu: {string.Join(", ", addComponent)}; CreateAssetMenu: {string.Join(", ", createAsset)})");
                }
        }

        // The package's own messages (dialogs, Console lines, exceptions, help boxes): a menu they send the user to must exist.
        foreach (var t in types)
        {
            var members = t.GetMembers(All);
            var texts = members.OfType<MethodBase>().SelectMany(m => StringLiterals(m).Select(text => (m.Name, text)))
                .Concat(members.Append(t).SelectMany(m => AttributeStrings(m).Select(text => (m.Name, text))));
            foreach (var (member, text) in texts)
                    foreach (Match match in MessageMenuPath.Matches(text))
                    {
                        string said = match.Groups[1].Value.Trim().TrimEnd('…').Trim();
                        var parts = MessageMenuStep.Split(said).Select(p => p.Trim().TrimEnd('…').Trim()).Where(p => p.Length > 0).ToArray();
                        if (UnityOwnMessageMenus.Any(u => string.Join("/", parts).StartsWith(u))) continue;
                        if (parts[0] == "Create") parts = new[] { "Assets" }.Concat(parts).ToArray();
                        string rest = string.Join("/", parts.Skip(1));
                        bool ok;
                        if (parts[0] == "Add Component") ok = addComponent.Contains(rest) || addComponent.Contains("Scripts/" + rest);
                        else
                        {
                            var full = string.Join("/", parts);
                            // A message may cut a name at its parenthesis ("… → In-betweening Model (shipped default)").
                            ok = menuItems.Any(p => p == full || p.StartsWith(full + "/") || p.StartsWith(full + " ("))
                                 || (parts.Length > 2 && parts[1] == "Create" && createAsset.Any(c => c == string.Join("/", parts.Skip(2)) || c.StartsWith(string.Join("/", parts.Skip(2)) + "/")));
                        }
                        if (!ok) Violations.Add($"menu: {t.Assembly.GetName().Name}: {t.FullName}.{member} says \"{said}\", a menu the package does not declare (MenuItem: {string.Join(", ", menuItems)}; CreateAssetMenu: {string.Join(", ", createAsset)})");
                    }
        }
    }

    // The string arguments of a member's attributes ([Tooltip("…")], [HelpURL], …): messages too.
    static IEnumerable<string> AttributeStrings(MemberInfo m)
    {
        IList<CustomAttributeData> attributes;
        try { attributes = m.GetCustomAttributesData(); }
        catch (Exception) { yield break; }
        foreach (var a in attributes)
            foreach (var arg in a.ConstructorArguments.Concat(a.NamedArguments.Select(n => n.TypedValue)))
                if (arg.Value is string text && (text.Contains('→') || text.Contains(" > "))) yield return text;
    }

    // The string literals a method loads (ldstr, 0x72, with a user-string token 0x70xxxxxx); a byte pattern that only
    // looks like one resolves to no string and is skipped.
    static IEnumerable<string> StringLiterals(MethodBase m)
    {
        byte[]? il;
        try { il = m.GetMethodBody()?.GetILAsByteArray(); }
        catch (Exception) { yield break; }
        if (il == null) yield break;
        for (int i = 0; i + 4 < il.Length; i++)
        {
            if (il[i] != 0x72 || il[i + 4] != 0x70) continue;
            string? s = null;
            try { s = m.Module.ResolveString(BitConverter.ToInt32(il, i + 1)); }
            catch (Exception) { }
            if (s != null && (s.Contains('→') || s.Contains(" > "))) yield return s;
        }
    }

    static bool IsMonoBehaviour(Type? t)
    {
        for (; t != null; t = t.BaseType) if (t.FullName == "UnityEngine.MonoBehaviour") return true;
        return false;
    }

    // UnityEditor.ObjectNames.NicifyVariableName: a space before each capital that follows a lower-case letter.
    static string Nicify(string name) => Regex.Replace(name, "(?<=[a-z0-9])(?=[A-Z])", " ");

    // ---- package -------------------------------------------------------------------------------------
    static void CheckPackageJson(string root)
    {
        var path = Path.Combine(root, "package.json");
        if (!File.Exists(path)) return;
        using var doc = JsonDocument.Parse(File.ReadAllText(path));
        foreach (var key in new[] { "documentationUrl", "changelogUrl", "licensesUrl" })
            if (doc.RootElement.TryGetProperty(key, out var v) && !Regex.IsMatch(v.GetString() ?? "", "^https?://"))
                Violations.Add($"package: package.json {key} is \"{v.GetString()}\": the Package Manager opens it as a web link, so it must be an absolute http(s) URL or absent");
    }

    // ---- friends -------------------------------------------------------------------------------------
    const string CoreAssembly = "DeltaInterpolator.Core";

    static void CheckFriends(List<Assembly> package, string dir)
    {
        var path = Path.Combine(dir, "assemblies.json");
        if (!File.Exists(path)) return;
        using var doc = JsonDocument.Parse(File.ReadAllText(path));
        foreach (var a in package)
            foreach (var attr in a.CustomAttributes.Where(c => c.AttributeType.FullName == "System.Runtime.CompilerServices.InternalsVisibleToAttribute"))
            {
                var friend = ((string)attr.ConstructorArguments[0].Value!).Split(',')[0].Trim();
                bool known = doc.RootElement.TryGetProperty(friend, out var info);
                bool test = known && info.GetProperty("test").GetBoolean();
                bool editorOnly = known && info.GetProperty("editorOnly").GetBoolean();
                if (a.GetName().Name == CoreAssembly)
                {
                    // Core is the engine-free library every other assembly builds on: its internals are for its tests.
                    if (!test) Violations.Add($"friends: {CoreAssembly} gives its internals to {friend}, which is not a test assembly of this configuration; make what it uses public (with XML docs) or move it into Core");
                }
                else if (!test && !editorOnly)
                {
                    Violations.Add($"friends: {a.GetName().Name} gives its internals to {friend}, which is neither a test assembly nor an Editor-only assembly of this configuration");
                }
            }
    }

    static string Name(Type t) => t.IsGenericType
        ? t.Name.Split('`')[0] + "<" + string.Join(", ", t.GetGenericArguments().Select(Name)) + ">"
        : t.Name;
}
