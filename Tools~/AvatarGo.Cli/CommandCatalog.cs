using System;
using System.Collections.Generic;
using System.Linq;

namespace AvatarGo.Cli;

/// <summary>Every <see cref="ICommand"/> in this assembly, found by reflection.</summary>
public static class CommandCatalog
{
    public static readonly IReadOnlyList<ICommand> All = typeof(CommandCatalog).Assembly.GetTypes()
        .Where(t => typeof(ICommand).IsAssignableFrom(t) && t.IsClass && !t.IsAbstract)
        .Select(t => (ICommand)Activator.CreateInstance(t))
        .OrderBy(c => c.Name, StringComparer.Ordinal)
        .ToList();

    /// <summary>The command whose name matches the most leading words of <paramref name="args"/>.</summary>
    public static ICommand Match(string[] args, out int consumedWords)
    {
        ICommand best = null;
        consumedWords = 0;
        foreach (ICommand c in All)
        {
            string[] words = c.Name.Split(' ');
            if (words.Length > args.Length || words.Length <= consumedWords) continue;
            bool match = true;
            for (int i = 0; i < words.Length; i++)
                if (!string.Equals(words[i], args[i], StringComparison.Ordinal)) { match = false; break; }
            if (match) { best = c; consumedWords = words.Length; }
        }
        return best;
    }
}
