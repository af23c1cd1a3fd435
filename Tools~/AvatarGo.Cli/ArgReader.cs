using System;
using System.Collections.Generic;
using System.Globalization;

namespace AvatarGo.Cli;

/// <summary>
/// Minimal option parser: positional arguments plus `--name value` and `--flag` options. Every option
/// a command accepts must be read; <see cref="ThrowOnUnknown"/> rejects the rest. An option given twice is a usage error.
/// </summary>
public sealed class ArgReader
{
    private readonly List<string> _positional = new();
    private readonly Dictionary<string, string> _options = new(StringComparer.Ordinal);
    private readonly HashSet<string> _read = new(StringComparer.Ordinal);

    public ArgReader(string[] args, params string[] flagNames)
    {
        var flags = new HashSet<string>(flagNames, StringComparer.Ordinal);
        for (int i = 0; i < args.Length; i++)
        {
            string a = args[i];
            if (a.StartsWith("--", StringComparison.Ordinal) && a.Length > 2)
            {
                string name = a.Substring(2);
                string value = "true";
                int eq = name.IndexOf('=');
                if (eq >= 0) { value = name.Substring(eq + 1); name = name.Substring(0, eq); }
                else if (!flags.Contains(name))
                {
                    // No value (the last argument, or another option next): said when the command reads the option, so
                    // that a misspelt flag is an unknown option and does not swallow the option after it.
                    bool next = i + 1 < args.Length && !(args[i + 1].StartsWith("--", StringComparison.Ordinal) && args[i + 1].Length > 2);
                    value = next ? args[++i] : null;
                }
                // The second of two values used to win silently (--frames 0:1 --frames 2:3 printed frame 2).
                if (_options.ContainsKey(name)) throw new UsageException($"option --{name} is given twice");
                _options[name] = value;
            }
            else _positional.Add(a);
        }
    }

    public IReadOnlyList<string> Positional => _positional;

    public string Positional0(string what)
    {
        if (_positional.Count == 0) throw new UsageException($"missing {what}");
        return _positional[0];
    }

    public bool Flag(string name)
    {
        _read.Add(name);
        return _options.TryGetValue(name, out string v) && v != "false";
    }

    public string String(string name, string fallback = null)
    {
        _read.Add(name);
        if (!_options.TryGetValue(name, out string v)) return fallback;
        return v ?? throw new UsageException($"option --{name} needs a value");
    }

    private const double MaxMagnitude = 1e12;

    public double Double(string name, double fallback)
    {
        _read.Add(name);
        if (!_options.TryGetValue(name, out string v)) return fallback;
        if (v == null) throw new UsageException($"option --{name} needs a value");
        if (!double.TryParse(v, NumberStyles.Float, CultureInfo.InvariantCulture, out double d) || double.IsNaN(d) || double.IsInfinity(d))
            throw new UsageException($"--{name} expects a number, got '{v}'");
        // No option takes more than this (fuzz inputs up to a trillion; millimetres, degrees, seconds, rates); beyond a float's range a value
        // became infinite where a command narrowed it and failed later, as an unreadable input (exit 1), not a bad argument.
        if (Math.Abs(d) > MaxMagnitude) throw new UsageException($"--{name} expects a number within ±{MaxMagnitude.ToString(CultureInfo.InvariantCulture)}, got '{v}'");
        return d;
    }

    public int Int(string name, int fallback)
    {
        _read.Add(name);
        if (!_options.TryGetValue(name, out string v)) return fallback;
        if (v == null) throw new UsageException($"option --{name} needs a value");
        if (!int.TryParse(v, NumberStyles.Integer, CultureInfo.InvariantCulture, out int n))
            throw new UsageException($"--{name} expects an integer, got '{v}'");
        return n;
    }

    /// <summary>Call after reading every option: rejects options the command does not know.</summary>
    public void ThrowOnUnknown(int maxPositional)
    {
        foreach (string name in _options.Keys)
            if (!_read.Contains(name)) throw new UsageException($"unknown option --{name}");
        if (_positional.Count > maxPositional)
            throw new UsageException($"unexpected argument '{_positional[maxPositional]}'");
    }
}
