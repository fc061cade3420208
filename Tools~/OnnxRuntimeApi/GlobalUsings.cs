// The UPM package's sources rely on Unity's implicit usings; .NET needs this one spelled out.
global using System.Reflection;
