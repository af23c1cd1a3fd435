using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using AvatarGo.Tools.Tests.AssetLint;
using AvatarGo.Tools.Tests.PackageLint;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace AvatarGo.Tools.Tests.Prefabs;

/// <summary>
/// Writes <c>Runtime/Prefabs/AvatarGo.prefab</c> from the components' own source: every serialized field of each
/// component (read by <see cref="ScriptCatalog"/>, the asset lint's reader of Unity's serialization rules) with its
/// initializer's value, or Unity's default when it has none, and the wiring below on top. So a renamed or added field
/// changes the generated prefab, and <c>PrefabGeneratorTests</c> fails until it is regenerated:
/// <c>AVATARGO_REGENERATE=1 dotnet test "Tools~/AvatarGo.Tools.Tests" -c Release --filter FullyQualifiedName~PrefabGenerator</c>.
/// </summary>
/// <remarks>
/// The layout: the root <c>AvatarGo</c> carries the calibrator and the fingers, its child <c>Tracking</c> the tracking
/// source (the default, <c>XRInputDevicesTrackingSource</c>: Unity XR input devices). The calibrator's avatar slots
/// (<c>m_Animator</c>, <c>m_AvatarRoot</c>) are empty; with <c>m_Driver</c> = Animator IK the calibrator adds the
/// <c>AvatarGoAnimatorIKDriver</c> to the assigned avatar's Animator (it needs the Animator on its own object, which an
/// empty slot cannot have), and the editor does the same when the avatar is assigned in the inspector. The fingers hold
/// Quest Touch controllers by default (Runtime/ControllerProfiles/quest-touch.json). File IDs are a hash of each object's
/// path, so regenerating gives the same bytes; Unity's YAML for 2021.3 (GameObject serializedVersion 6, Transform with
/// m_RootOrder).
/// </remarks>
public sealed class PrefabGenerator
{
    /// <summary>The prefab, package-relative.</summary>
    public const string PrefabPath = "Runtime/Prefabs/AvatarGo.prefab";

    /// <summary>The controller profile the fingers hold by default, package-relative.</summary>
    public const string DefaultControllerProfile = "Runtime/ControllerProfiles/quest-touch.json";

    private const long ScriptFileId = 11500000; // a MonoScript's file ID inside its .cs asset
    private const long TextAssetFileId = 4900000; // a TextAsset's file ID inside its imported file

    private readonly string _root;
    private readonly ScriptCatalog _scripts;
    private readonly Dictionary<string, string> _guids;
    private readonly Dictionary<string, CompilationUnitSyntax> _units = new(StringComparer.Ordinal);

    /// <summary>Reads the package at <paramref name="root"/>.</summary>
    public PrefabGenerator(string root)
    {
        _root = Path.GetFullPath(root);
        List<string> files = new PackageLinter(_root).Files.Where(PackageLinter.IsImported).ToList();
        _scripts = new ScriptCatalog(_root, files.Where(f => f.EndsWith(".cs", StringComparison.Ordinal)));
        _guids = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (string meta in files.Where(f => f.EndsWith(".meta", StringComparison.Ordinal)))
        {
            string line = File.ReadLines(Path.Combine(_root, meta)).FirstOrDefault(l => l.StartsWith("guid:", StringComparison.Ordinal));
            if (line != null) _guids[meta.Substring(0, meta.Length - ".meta".Length)] = line.Substring(5).Trim();
        }
    }

    private sealed record Component(string Script, long Id, Dictionary<string, string> Wiring);

    private sealed record Node(string Name, long GameObjectId, long TransformId, Node Parent, List<Component> Components, List<Node> Children);

    /// <summary>The prefab's text, as it is committed.</summary>
    public string Generate()
    {
        Node root = NewNode("AvatarGo", null);
        Node tracking = NewNode("Tracking", root);
        Component source = Add(tracking, "XRInputDevicesTrackingSource");
        Component calibrator = Add(root, "AvatarGoCalibrator");
        Component fingers = Add(root, "AvatarGoFingers");
        calibrator.Wiring["m_Source"] = Local(source.Id);
        calibrator.Wiring["m_Driver"] = EnumValue("AvatarGoCalibrator", "DriverKind", "AnimatorIK");
        fingers.Wiring["m_Calibrator"] = Local(calibrator.Id);
        string profile = $"{{fileID: {TextAssetFileId}, guid: {Guid(DefaultControllerProfile)}, type: 3}}";
        fingers.Wiring["m_LeftController"] = profile;
        fingers.Wiring["m_RightController"] = profile;

        var objects = new SortedDictionary<long, string>();
        Emit(root, objects);
        var text = new StringBuilder("%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n");
        foreach (string o in objects.Values) text.Append(o);
        return text.ToString();
    }

    private static Node NewNode(string name, Node parent)
    {
        string path = parent == null ? name : PathOf(parent) + "/" + name;
        var node = new Node(name, Id(path + "#GameObject"), Id(path + "#Transform"), parent, new List<Component>(), new List<Node>());
        parent?.Children.Add(node);
        return node;
    }

    private static string PathOf(Node node) => node.Parent == null ? node.Name : PathOf(node.Parent) + "/" + node.Name;

    private static Component Add(Node node, string script)
    {
        var c = new Component(script, Id(PathOf(node) + "#" + script), new Dictionary<string, string>(StringComparer.Ordinal));
        node.Components.Add(c);
        return c;
    }

    private static string Local(long id) => $"{{fileID: {id}}}";

    // A stable, positive 63-bit file ID (FNV-1a of the object's path): the same bytes on every run.
    private static long Id(string key)
    {
        ulong h = 14695981039346656037UL;
        foreach (byte b in Encoding.UTF8.GetBytes(key))
        {
            h ^= b;
            h *= 1099511628211UL;
        }
        return (long)(h & 0x7FFFFFFFFFFFFFFFUL) | 1L << 40;
    }

    private void Emit(Node node, SortedDictionary<long, string> objects)
    {
        var go = new StringBuilder();
        go.Append($"--- !u!1 &{node.GameObjectId}\nGameObject:\n");
        Header(go, null);
        go.Append("  serializedVersion: 6\n  m_Component:\n");
        go.Append($"  - component: {{fileID: {node.TransformId}}}\n");
        foreach (Component c in node.Components) go.Append($"  - component: {{fileID: {c.Id}}}\n");
        go.Append($"  m_Layer: 0\n  m_Name: {node.Name}\n  m_TagString: Untagged\n  m_Icon: {{fileID: 0}}\n  m_NavMeshLayer: 0\n");
        go.Append("  m_StaticEditorFlags: 0\n  m_IsActive: 1\n");
        objects.Add(node.GameObjectId, go.ToString());

        var t = new StringBuilder();
        t.Append($"--- !u!4 &{node.TransformId}\nTransform:\n");
        Header(t, node.GameObjectId);
        t.Append("  m_LocalRotation: {x: 0, y: 0, z: 0, w: 1}\n  m_LocalPosition: {x: 0, y: 0, z: 0}\n  m_LocalScale: {x: 1, y: 1, z: 1}\n");
        t.Append("  m_ConstrainProportionsScale: 0\n");
        if (node.Children.Count == 0) t.Append("  m_Children: []\n");
        else
        {
            t.Append("  m_Children:\n");
            foreach (Node child in node.Children) t.Append($"  - {{fileID: {child.TransformId}}}\n");
        }
        t.Append($"  m_Father: {{fileID: {(node.Parent == null ? 0 : node.Parent.TransformId)}}}\n");
        t.Append($"  m_RootOrder: {(node.Parent == null ? 0 : node.Parent.Children.IndexOf(node))}\n");
        t.Append("  m_LocalEulerAnglesHint: {x: 0, y: 0, z: 0}\n");
        objects.Add(node.TransformId, t.ToString());

        foreach (Component c in node.Components) objects.Add(c.Id, MonoBehaviour(node, c));
        foreach (Node child in node.Children) Emit(child, objects);
    }

    private static void Header(StringBuilder b, long? gameObject)
    {
        b.Append("  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {fileID: 0}\n  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n");
        if (gameObject != null) b.Append($"  m_GameObject: {{fileID: {gameObject}}}\n");
    }

    private string MonoBehaviour(Node node, Component c)
    {
        string file = ScriptFile(c.Script);
        ScriptType type = _scripts.MainTypeOf(file) ?? throw new InvalidOperationException($"{file} declares no class {c.Script}");
        var b = new StringBuilder();
        b.Append($"--- !u!114 &{c.Id}\nMonoBehaviour:\n");
        Header(b, node.GameObjectId);
        b.Append("  m_Enabled: 1\n  m_EditorHideFlags: 0\n");
        b.Append($"  m_Script: {{fileID: {ScriptFileId}, guid: {Guid(file)}, type: 3}}\n");
        b.Append("  m_Name:\n  m_EditorClassIdentifier:\n");
        var unused = new HashSet<string>(c.Wiring.Keys, StringComparer.Ordinal);
        foreach (ScriptField field in _scripts.AllFields(type).Where(f => f.Serialized))
        {
            unused.Remove(field.Name);
            string value = c.Wiring.TryGetValue(field.Name, out string wired) ? wired : DefaultValue(type, field);
            b.Append($"  {field.Name}:{(value.StartsWith('\n') ? value : " " + value)}\n");
        }
        if (unused.Count > 0)
            throw new InvalidOperationException($"{c.Script} has no serialized field {string.Join(", ", unused)}: the prefab's wiring names a field that is gone");
        return b.ToString();
    }

    private string ScriptFile(string className)
    {
        ScriptType t = _scripts.Find(className) ?? throw new InvalidOperationException($"no script declares {className}");
        return t.File;
    }

    private string Guid(string file) =>
        _guids.TryGetValue(file, out string g) ? g : throw new InvalidOperationException($"{file} has no .meta");

    // The value Unity writes for a field nobody changed: its initializer's, or the type's default.
    private string DefaultValue(ScriptType owner, ScriptField field)
    {
        ExpressionSyntax init = Initializer(owner, field.Name);
        string typeName = field.Type is GenericNameSyntax g ? g.Identifier.Text : field.TypeName.Split('.').Last();
        if (typeName == "UnityEvent")
            return "\n    m_PersistentCalls:\n      m_Calls: []";
        if (field.Type is ArrayTypeSyntax || field.Type is GenericNameSyntax { Identifier.Text: "List" })
        {
            if (init != null && init is not ImplicitArrayCreationExpressionSyntax && !init.ToString().Contains("[0]"))
                throw new InvalidOperationException($"{owner.Name}.{field.Name}: the generator writes only empty arrays and lists");
            return "[]";
        }
        ScriptType declared = _scripts.Find(typeName);
        if (declared?.Kind == "enum")
            return init == null ? EnumValues(declared).First().Value.ToString(CultureInfo.InvariantCulture)
                : EnumMember(declared, init).ToString(CultureInfo.InvariantCulture);
        if (ScriptCatalog.UnityObjectTypes.Contains(typeName) || (declared != null && _scripts.IsUnityScript(declared)))
        {
            if (init != null && !init.IsKind(SyntaxKind.NullLiteralExpression))
                throw new InvalidOperationException($"{owner.Name}.{field.Name}: an object reference initialized in code");
            return "{fileID: 0}";
        }
        switch (typeName)
        {
            case "bool":
                return init == null ? "0" : Literal(owner, field, init) is true ? "1" : "0";
            case "string":
                return init == null ? "" : (string)Literal(owner, field, init);
            case "float":
            case "double":
            case "int":
            case "long":
                if (init == null) return "0";
                object v = Literal(owner, field, init);
                return v switch
                {
                    float f => f.ToString("R", CultureInfo.InvariantCulture),
                    double d => ((float)d).ToString("R", CultureInfo.InvariantCulture),
                    _ => Convert.ToString(v, CultureInfo.InvariantCulture),
                };
            default:
                throw new InvalidOperationException($"{owner.Name}.{field.Name}: the generator does not know how Unity writes a {field.TypeName}");
        }
    }

    private static object Literal(ScriptType owner, ScriptField field, ExpressionSyntax e)
    {
        switch (e)
        {
            case LiteralExpressionSyntax l:
                return l.Token.Value;
            case PrefixUnaryExpressionSyntax { OperatorToken.Text: "-" } neg:
                return Literal(owner, field, neg.Operand) switch
                {
                    float f => -f,
                    double d => -d,
                    int i => -i,
                    long n => -n,
                    _ => throw new InvalidOperationException($"{owner.Name}.{field.Name}: cannot negate {neg.Operand}"),
                };
            default:
                throw new InvalidOperationException($"{owner.Name}.{field.Name}: the generator evaluates only literals, not '{e}'");
        }
    }

    private ExpressionSyntax Initializer(ScriptType owner, string field)
    {
        foreach (ScriptType t in Chain(owner))
        {
            VariableDeclaratorSyntax v = Unit(t.File).DescendantNodes().OfType<TypeDeclarationSyntax>()
                .Where(d => d.Identifier.Text == t.Name)
                .SelectMany(d => d.Members.OfType<FieldDeclarationSyntax>())
                .SelectMany(f => f.Declaration.Variables)
                .FirstOrDefault(x => x.Identifier.Text == field);
            if (v != null) return v.Initializer?.Value;
        }
        return null;
    }

    private IEnumerable<ScriptType> Chain(ScriptType type)
    {
        var seen = new HashSet<string>(StringComparer.Ordinal);
        for (ScriptType t = type; t != null && seen.Add(t.Name); t = t.BaseName == null ? null : _scripts.Find(t.BaseName))
            yield return t;
    }

    private CompilationUnitSyntax Unit(string file)
    {
        if (!_units.TryGetValue(file, out CompilationUnitSyntax unit))
            _units[file] = unit = CSharpSyntaxTree.ParseText(File.ReadAllText(Path.Combine(_root, file))).GetCompilationUnitRoot();
        return unit;
    }

    private string EnumValue(string owner, string enumName, string member)
    {
        ScriptType e = _scripts.Types.FirstOrDefault(t => t.Name == enumName && t.Kind == "enum" && t.File == ScriptFile(owner))
            ?? _scripts.Find(enumName) ?? throw new InvalidOperationException($"no enum {enumName}");
        return EnumValues(e).TryGetValue(member, out long v) ? v.ToString(CultureInfo.InvariantCulture)
            : throw new InvalidOperationException($"{enumName} has no member {member}");
    }

    private long EnumMember(ScriptType e, ExpressionSyntax init)
    {
        string member = init switch
        {
            MemberAccessExpressionSyntax m => m.Name.Identifier.Text,
            IdentifierNameSyntax id => id.Identifier.Text,
            _ => throw new InvalidOperationException($"an enum initializer the generator cannot read: '{init}'"),
        };
        return EnumValues(e).TryGetValue(member, out long v) ? v : throw new InvalidOperationException($"{e.Name} has no member {member}");
    }

    // Each member's value: its explicit literal, or one more than the member before.
    private Dictionary<string, long> EnumValues(ScriptType e)
    {
        EnumDeclarationSyntax d = Unit(e.File).DescendantNodes().OfType<EnumDeclarationSyntax>().First(x => x.Identifier.Text == e.Name);
        var values = new Dictionary<string, long>(StringComparer.Ordinal);
        long next = 0;
        foreach (EnumMemberDeclarationSyntax m in d.Members)
        {
            if (m.EqualsValue != null)
                next = m.EqualsValue.Value switch
                {
                    LiteralExpressionSyntax l => Convert.ToInt64(l.Token.Value, CultureInfo.InvariantCulture),
                    PrefixUnaryExpressionSyntax { OperatorToken.Text: "-", Operand: LiteralExpressionSyntax l } => -Convert.ToInt64(l.Token.Value, CultureInfo.InvariantCulture),
                    _ => throw new InvalidOperationException($"{e.Name}.{m.Identifier.Text}: a value the generator cannot read"),
                };
            values[m.Identifier.Text] = next++;
        }
        return values;
    }
}
