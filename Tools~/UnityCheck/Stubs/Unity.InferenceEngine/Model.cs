using System.Collections.Generic;

namespace Unity.InferenceEngine
{
    // source: inference:Runtime/Core/Model.cs
    public partial class Model
    {
        public partial struct Input
        {
            public string name;
            public DataType dataType;
            public DynamicTensorShape shape;
        }

        public partial struct Output
        {
            public string name;
        }

        public List<Input> inputs;
        public List<Output> outputs;
    }
}
