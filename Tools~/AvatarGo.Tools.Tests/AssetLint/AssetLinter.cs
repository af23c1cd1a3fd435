using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using AvatarGo.Tools.Tests.PackageLint;
using YamlDotNet.RepresentationModel;

namespace AvatarGo.Tools.Tests.AssetLint;

/// <summary>
/// Checks the package's Unity assets as Unity will read them: every .prefab, .unity, .asset, .controller and .mat
/// is Unity YAML that parses (<see cref="UnityYaml"/>); every reference with no guid names an object of the same file,
/// every reference with a guid names an asset of the package or a built-in Unity resource; every MonoBehaviour's
/// m_Script is the .meta GUID of a package script whose class is named after its file and derives from MonoBehaviour
/// or ScriptableObject (or a documented Unity script); and every field it sets is one Unity serializes on that class
/// (<see cref="ScriptCatalog"/>), recursively into [Serializable] values. .inputactions files are JSON and must parse
/// with an action-map list. Not checked: prefab-instance modifications (propertyPath), the values' types.
/// </summary>
public sealed class AssetLinter
{
    /// <summary>The asset kinds checked.</summary>
    public static readonly IReadOnlyList<string> Extensions = new[] { ".prefab", ".unity", ".asset", ".controller", ".mat", ".inputactions" };

    /// <summary>
    /// GUIDs of Unity's built-in resources that assets reference: "unity default resources" (0...f0...) and
    /// "unity_builtin_extra" (0...e0...), as written in Unity's YAML (not from Unity's C# sources).
    /// </summary>
    public static readonly IReadOnlyDictionary<string, string> BuiltInResources = new Dictionary<string, string>(StringComparer.Ordinal)
    {
        ["0000000000000000f000000000000000"] = "unity default resources",
        ["0000000000000000e000000000000000"] = "unity_builtin_extra",
    };

    /// <summary>
    /// Unity scripts outside the package a prefab may use (m_Script GUID to class), each with where its GUID is
    /// documented. Empty until the package's assets use one; their fields are not checked (their sources are not here).
    /// </summary>
    public static readonly IReadOnlyDictionary<string, string> DocumentedUnityScripts = new Dictionary<string, string>(StringComparer.Ordinal);

    /// <summary>The keys Unity writes for every MonoBehaviour besides its script's fields.</summary>
    public static readonly IReadOnlySet<string> MonoBehaviourKeys = new HashSet<string>(StringComparer.Ordinal)
    {
        "m_ObjectHideFlags", "m_CorrespondingSourceObject", "m_PrefabInstance", "m_PrefabAsset", "m_GameObject", "m_Enabled",
        "m_EditorHideFlags", "m_Script", "m_Name", "m_EditorClassIdentifier", "serializedVersion",
    };

    private readonly string _root;
    private readonly IReadOnlyList<string> _files;
    private readonly IReadOnlyDictionary<string, string> _documentedScripts;

    /// <summary>Lints the package at <paramref name="root"/> (files as <see cref="PackageLinter.Files"/> lists them).</summary>
    public AssetLinter(string root, IReadOnlyDictionary<string, string> documentedScripts = null)
    {
        _root = Path.GetFullPath(root);
        _files = new PackageLinter(_root).Files.Where(PackageLinter.IsImported).ToList();
        _documentedScripts = documentedScripts ?? DocumentedUnityScripts;
    }

    /// <summary>The assets checked, package-relative.</summary>
    public List<string> Assets => _files.Where(f => Extensions.Contains(Path.GetExtension(f).ToLowerInvariant())).ToList();

    /// <summary>Every problem, each naming the file (and line or object).</summary>
    public List<string> Check()
    {
        var problems = new List<string>();
        List<string> assets = Assets;
        if (assets.Count == 0) return problems;
        var guidToFile = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (string meta in _files.Where(f => f.EndsWith(".meta", StringComparison.Ordinal)))
        {
            string line = File.ReadLines(Path.Combine(_root, meta)).FirstOrDefault(l => l.StartsWith("guid:", StringComparison.Ordinal));
            if (line != null) guidToFile[line.Substring(5).Trim()] = meta.Substring(0, meta.Length - ".meta".Length);
        }
        var scripts = new ScriptCatalog(_root, _files.Where(f => f.EndsWith(".cs", StringComparison.Ordinal)));
        foreach (string asset in assets)
        {
            string text = File.ReadAllText(Path.Combine(_root, asset));
            if (asset.EndsWith(".inputactions", StringComparison.OrdinalIgnoreCase))
            {
                CheckInputActions(asset, text, problems);
                continue;
            }
            List<UnityYamlObject> objects;
            try
            {
                objects = UnityYaml.Parse(text);
            }
            catch (FormatException e)
            {
                problems.Add($"{asset}: not Unity YAML: {e.Message}");
                continue;
            }
            var ids = new HashSet<long>(objects.Select(o => o.FileId));
            foreach (UnityYamlObject o in objects)
            {
                string at = $"{asset}:{o.Line} {o.ClassName} &{o.FileId}";
                foreach (var (path, fileId, guid, _) in UnityYaml.References(o.Body))
                {
                    if (string.IsNullOrEmpty(guid) || guid.Trim('0').Length == 0)
                    {
                        if (fileId != 0 && !ids.Contains(fileId))
                            problems.Add($"{at}: {path} refers to fileID {fileId}, which is no object of this file");
                    }
                    else if (o.ClassId == 114 && path == "m_Script")
                        continue; // CheckMonoBehaviour says what is wrong with it
                    else if (!guidToFile.ContainsKey(guid) && !BuiltInResources.ContainsKey(guid) && !_documentedScripts.ContainsKey(guid))
                        problems.Add($"{at}: {path} refers to guid {guid}, which is no asset of the package nor a built-in Unity resource");
                }
                if (o.ClassId == 114 && !o.Stripped) CheckMonoBehaviour(at, o, guidToFile, scripts, problems);
            }
        }
        return problems;
    }

    private void CheckMonoBehaviour(string at, UnityYamlObject o, Dictionary<string, string> guidToFile, ScriptCatalog scripts, List<string> problems)
    {
        if (!o.Body.Children.TryGetValue(new YamlScalarNode("m_Script"), out YamlNode scriptNode) || scriptNode is not YamlMappingNode script ||
            !script.Children.TryGetValue(new YamlScalarNode("guid"), out YamlNode guidNode))
        {
            problems.Add($"{at}: a MonoBehaviour without an m_Script guid");
            return;
        }
        string guid = ((YamlScalarNode)guidNode).Value;
        if (_documentedScripts.ContainsKey(guid)) return;
        if (!guidToFile.TryGetValue(guid, out string file) || !file.EndsWith(".cs", StringComparison.Ordinal))
        {
            problems.Add($"{at}: m_Script guid {guid} is no script of the package nor a documented Unity script");
            return;
        }
        ScriptType type = scripts.MainTypeOf(file);
        if (type == null)
        {
            problems.Add($"{at}: m_Script is {file}, which declares no class named {Path.GetFileNameWithoutExtension(file)} (Unity finds the script's class by file name)");
            return;
        }
        if (!scripts.IsUnityScript(type))
        {
            problems.Add($"{at}: m_Script is {file}, whose class {type.Name} derives from neither MonoBehaviour nor ScriptableObject");
            return;
        }
        CheckFields(at, type.Name, o.Body, scripts.AllFields(type), scripts, problems, MonoBehaviourKeys);
    }

    private static void CheckFields(string at, string typeName, YamlMappingNode body, List<ScriptField> fields, ScriptCatalog scripts,
        List<string> problems, IReadOnlySet<string> builtInKeys)
    {
        foreach (var (keyNode, value) in body.Children)
        {
            string key = ((YamlScalarNode)keyNode).Value;
            if (builtInKeys != null && builtInKeys.Contains(key)) continue;
            ScriptField field = fields.FirstOrDefault(f => f.Name == key) ?? fields.FirstOrDefault(f => f.FormerNames.Contains(key));
            if (field == null)
            {
                problems.Add($"{at}: sets '{key}', but {typeName} has no such field");
                continue;
            }
            if (!field.Serialized)
            {
                problems.Add($"{at}: sets '{key}', but Unity does not serialize {typeName}.{field.Name} ({field.WhyNot})");
                continue;
            }
            // A [Serializable] value of the package: its keys must be that type's serialized fields too.
            string element = field.Type is Microsoft.CodeAnalysis.CSharp.Syntax.ArrayTypeSyntax arr ? arr.ElementType.ToString()
                : field.Type is Microsoft.CodeAnalysis.CSharp.Syntax.GenericNameSyntax { Identifier.Text: "List" } list ? list.TypeArgumentList.Arguments[0].ToString()
                : field.TypeName;
            ScriptType nested = scripts.Find(element.Split('.').Last());
            if (nested == null || nested.Kind == "enum" || scripts.IsUnityScript(nested)) continue;
            IEnumerable<YamlMappingNode> values = value is YamlSequenceNode seq ? seq.Children.OfType<YamlMappingNode>()
                : value is YamlMappingNode m ? new[] { m } : Array.Empty<YamlMappingNode>();
            foreach (YamlMappingNode v in values)
                CheckFields($"{at} {key}", nested.Name, v, scripts.AllFields(nested), scripts, problems, null);
        }
    }

    private static void CheckInputActions(string asset, string text, List<string> problems)
    {
        try
        {
            using JsonDocument doc = JsonDocument.Parse(text);
            if (doc.RootElement.ValueKind != JsonValueKind.Object || !doc.RootElement.TryGetProperty("maps", out JsonElement maps) || maps.ValueKind != JsonValueKind.Array)
                problems.Add($"{asset}: an .inputactions file is a JSON object with a \"maps\" array");
        }
        catch (JsonException e)
        {
            problems.Add($"{asset}: not valid JSON ({e.Message})");
        }
    }
}
