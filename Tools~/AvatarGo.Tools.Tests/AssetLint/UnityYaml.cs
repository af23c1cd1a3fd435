using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using YamlDotNet.Core;
using YamlDotNet.RepresentationModel;

namespace AvatarGo.Tools.Tests.AssetLint;

/// <summary>One object of a Unity YAML file: a document "--- !u!CLASSID &amp;FILEID [stripped]" holding "ClassName: {...}".</summary>
/// <param name="ClassId">Unity's class id (1 GameObject, 4 Transform, 114 MonoBehaviour, 1001 PrefabInstance, ...).</param>
/// <param name="FileId">The object's local file id (its anchor).</param>
/// <param name="Stripped">True for a "stripped" stand-in of an object of a nested prefab.</param>
/// <param name="ClassName">The single key of the document's mapping.</param>
/// <param name="Body">The mapping under <paramref name="ClassName"/>.</param>
/// <param name="Line">The 1-based line of the document header.</param>
public sealed record UnityYamlObject(int ClassId, long FileId, bool Stripped, string ClassName, YamlMappingNode Body, int Line);

/// <summary>
/// Reads Unity's text serialization with YamlDotNet. Unity writes "%YAML 1.1" and "%TAG !u! tag:unity3d.com,2011:"
/// once at the top and then one document per object, "--- !u!114 &amp;11400000"; YAML scopes directives to the next
/// document only, and "stripped" after the anchor is not YAML. So each header is rewritten to the verbatim tag
/// "--- !&lt;tag:unity3d.com,2011:114&gt; &amp;11400000" (same meaning, valid in every document) before YamlDotNet parses
/// the stream; everything else is parsed as written.
/// </summary>
public static class UnityYaml
{
    private static readonly Regex Header = new(@"^--- !u!(?<class>\d+) &(?<id>-?\d+)(?<stripped> stripped)?\s*$", RegexOptions.CultureInvariant);

    /// <summary>Parses a Unity YAML file; throws <see cref="FormatException"/> naming the line for anything Unity could not load.</summary>
    public static List<UnityYamlObject> Parse(string text)
    {
        string[] lines = text.Replace("\r\n", "\n").Split('\n');
        if (lines.Length < 2 || lines[0] != "%YAML 1.1" || lines[1] != "%TAG !u! tag:unity3d.com,2011:")
            throw new FormatException("line 1: a Unity YAML file starts with '%YAML 1.1' and '%TAG !u! tag:unity3d.com,2011:'");
        var headers = new List<(int Line, int ClassId, long FileId, bool Stripped)>();
        var rewritten = new List<string>(lines.Length);
        for (int i = 0; i < lines.Length; i++)
        {
            string line = lines[i];
            if (line.StartsWith("---", StringComparison.Ordinal))
            {
                Match m = Header.Match(line);
                if (!m.Success) throw new FormatException($"line {i + 1}: '{line}' is not a Unity object header '--- !u!CLASSID &FILEID'");
                headers.Add((i + 1, int.Parse(m.Groups["class"].Value), long.Parse(m.Groups["id"].Value), m.Groups["stripped"].Success));
                line = $"--- !<tag:unity3d.com,2011:{m.Groups["class"].Value}> &{m.Groups["id"].Value}";
            }
            rewritten.Add(line);
        }
        var stream = new YamlStream();
        try
        {
            stream.Load(new StringReader(string.Join("\n", rewritten)));
        }
        catch (YamlException e)
        {
            throw new FormatException($"line {e.Start.Line}: {e.Message}");
        }
        catch (InvalidOperationException e)
        {
            // YamlDotNet's scanner fails this way on some malformed flow collections.
            throw new FormatException($"line ?: {e.Message}");
        }
        if (stream.Documents.Count != headers.Count)
            throw new FormatException($"{headers.Count} object header(s) but {stream.Documents.Count} YAML document(s)");
        var objects = new List<UnityYamlObject>();
        for (int i = 0; i < headers.Count; i++)
        {
            var (line, classId, fileId, stripped) = headers[i];
            if (stream.Documents[i].RootNode is not YamlMappingNode root || root.Children.Count != 1 ||
                root.Children.Single().Key is not YamlScalarNode name)
                throw new FormatException($"line {line}: an object document holds one 'ClassName:' mapping");
            YamlMappingNode body = root.Children.Single().Value as YamlMappingNode ?? new YamlMappingNode();
            objects.Add(new UnityYamlObject(classId, fileId, stripped, name.Value, body, line));
        }
        var duplicate = objects.GroupBy(o => o.FileId).FirstOrDefault(g => g.Count() > 1);
        if (duplicate != null) throw new FormatException($"line {duplicate.Last().Line}: file id {duplicate.Key} is used twice");
        return objects;
    }

    /// <summary>Every "{fileID: N[, guid: G, type: T]}" reference under a node, with the path of keys leading to it.</summary>
    public static IEnumerable<(string Path, long FileId, string Guid, YamlMappingNode Node)> References(YamlNode node, string path = "")
    {
        switch (node)
        {
            case YamlMappingNode map:
                if (map.Children.TryGetValue(new YamlScalarNode("fileID"), out YamlNode id) && id is YamlScalarNode s && long.TryParse(s.Value, out long fileId))
                {
                    string guid = map.Children.TryGetValue(new YamlScalarNode("guid"), out YamlNode g) ? ((YamlScalarNode)g).Value : null;
                    yield return (path, fileId, guid, map);
                    yield break;
                }
                foreach (var (key, value) in map.Children)
                    foreach (var r in References(value, path.Length == 0 ? ((YamlScalarNode)key).Value : path + "." + ((YamlScalarNode)key).Value))
                        yield return r;
                break;
            case YamlSequenceNode seq:
                int i = 0;
                foreach (YamlNode item in seq.Children)
                    foreach (var r in References(item, $"{path}[{i++}]"))
                        yield return r;
                break;
        }
    }
}
