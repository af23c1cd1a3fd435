using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace AvatarGo.Tools.Tests.AssetLint;

/// <summary>A field as Unity's serializer sees it.</summary>
/// <param name="Name">The field name (the YAML key).</param>
/// <param name="FormerNames">Names from [FormerlySerializedAs], which Unity still reads.</param>
/// <param name="TypeName">The field's type as written.</param>
/// <param name="Serialized">True when Unity serializes it.</param>
/// <param name="WhyNot">Why Unity does not, when it does not.</param>
public sealed record ScriptField(string Name, IReadOnlyList<string> FormerNames, TypeSyntax Type, string TypeName, bool Serialized, string WhyNot);

/// <summary>A class, struct or enum declared in the package's scripts.</summary>
/// <param name="Name">The type's name.</param>
/// <param name="File">The .cs file, package-relative.</param>
/// <param name="Kind">"class", "struct" or "enum".</param>
/// <param name="BaseName">The first base type's simple name, or null.</param>
/// <param name="IsSerializable">True with [Serializable].</param>
/// <param name="IsAbstractOrGeneric">Abstract or generic: Unity cannot create it from YAML.</param>
/// <param name="Fields">Its own fields, in order.</param>
public sealed record ScriptType(string Name, string File, string Kind, string BaseName, bool IsSerializable, bool IsAbstractOrGeneric, IReadOnlyList<ScriptField> Fields);

/// <summary>
/// The package's scripts read with Roslyn (syntax only: the asset lint needs names, bases, modifiers and attributes,
/// not a compile), and Unity's rules for what it serializes: instance fields (not static, const or readonly) that are
/// public or [SerializeField] (or [SerializeReference]) and not [NonSerialized], of a type Unity serializes:
/// primitives, string, enums, UnityEngine.Object references, Unity's math and color structs, [Serializable] classes
/// and structs, and single-level arrays or List&lt;T&gt; of those (Unity manual, "Script serialization").
/// </summary>
public sealed class ScriptCatalog
{
    /// <summary>Unity's built-in value types the serializer handles (Unity manual, "Script serialization").</summary>
    public static readonly IReadOnlySet<string> UnityValueTypes = new HashSet<string>(StringComparer.Ordinal)
    {
        "Vector2", "Vector3", "Vector4", "Vector2Int", "Vector3Int", "Quaternion", "Matrix4x4", "Color", "Color32", "Rect", "RectInt",
        "Bounds", "BoundsInt", "LayerMask", "AnimationCurve", "Gradient", "RectOffset", "GUIStyle", "Hash128",
    };

    /// <summary>UnityEngine.Object types a field may reference (serialized as {fileID, guid}); extend as the package uses more.</summary>
    public static readonly IReadOnlySet<string> UnityObjectTypes = new HashSet<string>(StringComparer.Ordinal)
    {
        "Object", "GameObject", "Component", "Behaviour", "MonoBehaviour", "ScriptableObject", "Transform", "RectTransform", "Animator",
        "Avatar", "RuntimeAnimatorController", "AnimationClip", "Material", "Mesh", "Shader", "Texture", "Texture2D", "Sprite",
        "Renderer", "MeshRenderer", "SkinnedMeshRenderer", "LineRenderer", "Camera", "Light", "AudioClip", "TextAsset", "Font",
        "Collider", "Rigidbody", "InputActionAsset", "InputActionReference",
        "XROrigin", // com.unity.xr.core-utils: a MonoBehaviour
    };

    /// <summary>
    /// Unity's classes the serializer writes by value: <c>UnityEvent</c> and, from Unity 2020.1, the generic
    /// <c>UnityEvent&lt;T0..T3&gt;</c> fields themselves (Unity manual, "Script serialization"); each is written as
    /// <c>m_PersistentCalls: {m_Calls: [...]}</c>.
    /// </summary>
    public static readonly IReadOnlySet<string> UnitySerializableClasses = new HashSet<string>(StringComparer.Ordinal)
    {
        "UnityEvent",
        "InputActionProperty", // com.unity.inputsystem: a [Serializable] struct (m_UseReference, m_Action, m_Reference)
    };

    private static readonly IReadOnlySet<string> Primitives = new HashSet<string>(StringComparer.Ordinal)
    {
        "bool", "byte", "sbyte", "short", "ushort", "int", "uint", "long", "ulong", "float", "double", "char", "string",
        "Boolean", "Byte", "SByte", "Int16", "UInt16", "Int32", "UInt32", "Int64", "UInt64", "Single", "Double", "Char", "String",
    };

    private readonly Dictionary<string, ScriptType> _typesByName = new(StringComparer.Ordinal);

    /// <summary>Reads every .cs file in <paramref name="scripts"/> (package-relative paths) under <paramref name="root"/>.</summary>
    public ScriptCatalog(string root, IEnumerable<string> scripts)
    {
        // Two passes: a field's type may be declared further down, or in another file.
        var declarations = new List<(BaseTypeDeclarationSyntax Syntax, string File)>();
        foreach (string file in scripts)
        {
            CompilationUnitSyntax unit = CSharpSyntaxTree.ParseText(File.ReadAllText(Path.Combine(root, file))).GetCompilationUnitRoot();
            foreach (BaseTypeDeclarationSyntax t in unit.DescendantNodes().OfType<BaseTypeDeclarationSyntax>())
            {
                declarations.Add((t, file));
                _typesByName.TryAdd(t.Identifier.Text, Read(t, file, withFields: false)); // duplicate names: the first wins (a lint, not a compiler)
            }
        }
        foreach (var (t, file) in declarations)
        {
            ScriptType type = Read(t, file, withFields: true);
            if (_typesByName[type.Name].File == file) _typesByName[type.Name] = type;
            Types.Add(type);
        }
    }

    /// <summary>Every type declared in the scripts.</summary>
    public List<ScriptType> Types { get; } = new();

    /// <summary>The type named after the file (what Unity requires of a MonoBehaviour or ScriptableObject script), or null.</summary>
    public ScriptType MainTypeOf(string file) =>
        Types.FirstOrDefault(t => t.File == file && t.Name == Path.GetFileNameWithoutExtension(file) && t.Kind == "class");

    /// <summary>True when the class derives, through package classes, from MonoBehaviour or ScriptableObject.</summary>
    public bool IsUnityScript(ScriptType type)
    {
        var seen = new HashSet<string>(StringComparer.Ordinal);
        for (ScriptType t = type; t != null && seen.Add(t.Name);)
        {
            if (t.BaseName is "MonoBehaviour" or "ScriptableObject" || (t.BaseName != null && UnityObjectTypes.Contains(t.BaseName) && t.BaseName != "Object"))
                return t.BaseName is "MonoBehaviour" or "ScriptableObject";
            t = t.BaseName != null && _typesByName.TryGetValue(t.BaseName, out ScriptType b) ? b : null;
        }
        return false;
    }

    /// <summary>The serialized fields of a type, its package base classes' first (as Unity writes them).</summary>
    public List<ScriptField> AllFields(ScriptType type)
    {
        var chain = new List<ScriptType>();
        var seen = new HashSet<string>(StringComparer.Ordinal);
        for (ScriptType t = type; t != null && seen.Add(t.Name); t = t.BaseName != null && _typesByName.TryGetValue(t.BaseName, out ScriptType b) ? b : null)
            chain.Insert(0, t);
        return chain.SelectMany(t => t.Fields).ToList();
    }

    /// <summary>The package type with this simple name, or null.</summary>
    public ScriptType Find(string name) => _typesByName.TryGetValue(name, out ScriptType t) ? t : null;

    /// <summary>Why Unity would not serialize a field of this type, or null when it would.</summary>
    public string WhyNotSerializable(TypeSyntax type, bool inCollection = false)
    {
        switch (type)
        {
            case NullableTypeSyntax:
                return "a Nullable<T> is not serialized";
            case ArrayTypeSyntax array:
                if (array.RankSpecifiers.Count > 1 || array.RankSpecifiers[0].Rank > 1) return "a multidimensional or jagged array is not serialized";
                return inCollection ? "an array inside an array or List is not serialized" : WhyNotSerializable(array.ElementType, inCollection: true);
            case GenericNameSyntax { Identifier.Text: "List", TypeArgumentList.Arguments.Count: 1 } list:
                return inCollection ? "a List inside an array or List is not serialized" : WhyNotSerializable(list.TypeArgumentList.Arguments[0], inCollection: true);
            case GenericNameSyntax { TypeArgumentList.Arguments.Count: <= 4 } evt when UnitySerializableClasses.Contains(evt.Identifier.Text):
                foreach (TypeSyntax argument in evt.TypeArgumentList.Arguments)
                    if (WhyNotSerializable(argument, inCollection: true) is string why) return $"{evt}: {why}";
                return null;
            case GenericNameSyntax generic:
                return $"{generic.Identifier.Text}<...> is not a type Unity serializes";
            case QualifiedNameSyntax qualified:
                return WhyNotSerializable(qualified.Right, inCollection);
            case AliasQualifiedNameSyntax alias:
                return WhyNotSerializable(alias.Name, inCollection);
            case PredefinedTypeSyntax predefined:
                return Primitives.Contains(predefined.Keyword.Text) ? null : $"{predefined.Keyword.Text} is not a type Unity serializes";
            case IdentifierNameSyntax name:
                string n = name.Identifier.Text;
                if (Primitives.Contains(n) || UnityValueTypes.Contains(n) || UnityObjectTypes.Contains(n) || UnitySerializableClasses.Contains(n)) return null;
                ScriptType t = Find(n);
                if (t == null) return $"{n} is neither a Unity-serializable type nor a type of the package";
                if (t.Kind == "enum") return null;
                if (t.Kind == "class" && IsUnityScript(t)) return null; // a reference to another component or asset
                if (t.IsAbstractOrGeneric) return $"{n} is abstract or generic";
                return t.IsSerializable ? null : $"{n} lacks [Serializable]";
            default:
                return $"{type} is not a type Unity serializes";
        }
    }

    private ScriptType Read(BaseTypeDeclarationSyntax t, string file, bool withFields)
    {
        string kind = t switch { EnumDeclarationSyntax => "enum", StructDeclarationSyntax => "struct", ClassDeclarationSyntax => "class", _ => "other" };
        string baseName = t.BaseList?.Types.FirstOrDefault()?.Type switch
        {
            IdentifierNameSyntax id => id.Identifier.Text,
            QualifiedNameSyntax q => q.Right.Identifier.Text,
            GenericNameSyntax g => g.Identifier.Text,
            _ => null,
        };
        bool serializable = HasAttribute(t.AttributeLists, "Serializable");
        bool abstractOrGeneric = t.Modifiers.Any(SyntaxKind.AbstractKeyword) || (t is TypeDeclarationSyntax { TypeParameterList: not null });
        var fields = new List<ScriptField>();
        if (withFields && t is TypeDeclarationSyntax td)
            foreach (FieldDeclarationSyntax f in td.Members.OfType<FieldDeclarationSyntax>())
                foreach (VariableDeclaratorSyntax v in f.Declaration.Variables)
                    fields.Add(ReadField(f, v));
        return new ScriptType(t.Identifier.Text, file, kind, baseName, serializable, abstractOrGeneric, fields);
    }

    private ScriptField ReadField(FieldDeclarationSyntax f, VariableDeclaratorSyntax v)
    {
        string why = null;
        bool serializeField = HasAttribute(f.AttributeLists, "SerializeField");
        bool serializeReference = HasAttribute(f.AttributeLists, "SerializeReference");
        if (f.Modifiers.Any(SyntaxKind.StaticKeyword)) why = "static";
        else if (f.Modifiers.Any(SyntaxKind.ConstKeyword)) why = "const";
        else if (f.Modifiers.Any(SyntaxKind.ReadOnlyKeyword)) why = "readonly";
        else if (HasAttribute(f.AttributeLists, "NonSerialized")) why = "[NonSerialized]";
        else if (!f.Modifiers.Any(SyntaxKind.PublicKeyword) && !serializeField && !serializeReference) why = "neither public nor [SerializeField]";
        TypeSyntax fieldType = ResolveAlias(f.Declaration.Type);
        if (why == null && !serializeReference) why = WhyNotSerializable(fieldType);
        var former = f.AttributeLists.SelectMany(l => l.Attributes)
            .Where(a => AttributeName(a) == "FormerlySerializedAs" && a.ArgumentList?.Arguments.Count > 0)
            .Select(a => (a.ArgumentList.Arguments[0].Expression as LiteralExpressionSyntax)?.Token.ValueText)
            .Where(s => s != null).ToList();
        return new ScriptField(v.Identifier.Text, former, fieldType, fieldType.ToString(), why == null, why);
    }

    // A field typed by a using alias of its file (`using CoreScaleMode = AvatarGo.Core.ScaleMode;`) has the alias's target type.
    private static TypeSyntax ResolveAlias(TypeSyntax type)
    {
        if (type is not IdentifierNameSyntax name || type.SyntaxTree == null) return type;
        foreach (UsingDirectiveSyntax u in type.SyntaxTree.GetCompilationUnitRoot().DescendantNodes().OfType<UsingDirectiveSyntax>())
            if (u.Alias != null && u.Alias.Name.Identifier.Text == name.Identifier.Text && u.Name != null) return u.Name;
        return type;
    }

    private static bool HasAttribute(SyntaxList<AttributeListSyntax> lists, string name) =>
        lists.SelectMany(l => l.Attributes).Any(a => AttributeName(a) == name);

    private static string AttributeName(AttributeSyntax a)
    {
        string n = a.Name switch
        {
            QualifiedNameSyntax q => q.Right.Identifier.Text,
            IdentifierNameSyntax id => id.Identifier.Text,
            AliasQualifiedNameSyntax al => al.Name.Identifier.Text,
            _ => a.Name.ToString(),
        };
        return n.EndsWith("Attribute", StringComparison.Ordinal) ? n.Substring(0, n.Length - "Attribute".Length) : n;
    }
}
